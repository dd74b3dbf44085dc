// Effective moduli of a porous layer: the Hashin–Shtrikman bounds of a two-phase material
// (Eq. 5.1–5.2) and their convex combination (Eq. 5.3), with the pores a very compliant phase
// (κ₁ = Cκ₂, µ₁ = Cµ₂, volume fraction p), as the reference's Section 5.2.2 sets them up.
//
// Reference: Hashin & Shtrikman, J. Mech. Phys. Solids 11 (1963) 127–140; the reference's
// Eq. 5.1–5.3. With C → 0 the upper bound tends to the known porous limits
// κ⁺ = 4κµ(1 − p)/(4µ + 3pκ) (tests/verification/test_porous_damage.cpp) and the lower to 0.
//
//     surfaces { target { ... interaction erode;
//                         erosion { porosity 0.2; boundWeight 0.5; } } }
#pragma once

namespace slides {

/// A pair of bounds on a modulus [Pa].
struct ModulusBounds {
    double lower = 0;
    double upper = 0;
};

/// Bulk and shear moduli [Pa].
struct IsotropicModuli {
    double bulk = 0;
    double shear = 0;
};

/// Eq. 5.1: the bounds on the bulk modulus of phases 1 (the softer) and 2, with v2 the volume
/// fraction of phase 2; written without 1/(κ₂ − κ₁), so equal phases give their modulus.
inline ModulusBounds hashinShtrikmanBulk(const IsotropicModuli& soft, const IsotropicModuli& stiff,
                                         double stiffFraction) {
    const double v2 = stiffFraction, difference = stiff.bulk - soft.bulk;
    return {soft.bulk + v2 * difference /
                            (1 + 3 * (1 - v2) * difference / (3 * soft.bulk + 4 * soft.shear)),
            stiff.bulk - (1 - v2) * difference /
                             (1 - 3 * v2 * difference / (3 * stiff.bulk + 4 * stiff.shear))};
}

/// Eq. 5.2: the bounds on the shear modulus, as hashinShtrikmanBulk.
inline ModulusBounds hashinShtrikmanShear(const IsotropicModuli& soft, const IsotropicModuli& stiff,
                                          double stiffFraction) {
    const double v2 = stiffFraction, difference = stiff.shear - soft.shear;
    const auto weight = [](const IsotropicModuli& m) {
        return 6 * (m.bulk + 2 * m.shear) / (5 * m.shear * (3 * m.bulk + 4 * m.shear));
    };
    return {soft.shear + v2 * difference / (1 + (1 - v2) * difference * weight(soft)),
            stiff.shear - (1 - v2) * difference / (1 - v2 * difference * weight(stiff))};
}

/// The pores' moduli per the matrix's: the reference finds the estimates insensitive to C
/// below ≈ 1e-4.
inline constexpr double poreStiffnessRatio = 1e-4;

/// Eq. 5.3: the moduli of a matrix with pores of volume fraction porosity, the convex
/// combination φ·upper + (1 − φ)·lower of the bounds (φ = boundWeight ∈ [0, 1]).
inline IsotropicModuli porousModuli(const IsotropicModuli& matrix, double porosity,
                                    double boundWeight,
                                    double stiffnessRatio = poreStiffnessRatio) {
    const IsotropicModuli pores{stiffnessRatio * matrix.bulk, stiffnessRatio * matrix.shear};
    const ModulusBounds bulk = hashinShtrikmanBulk(pores, matrix, 1 - porosity);
    const ModulusBounds shear = hashinShtrikmanShear(pores, matrix, 1 - porosity);
    const auto combine = [boundWeight](const ModulusBounds& b) {
        return boundWeight * b.upper + (1 - boundWeight) * b.lower;
    };
    return {combine(bulk), combine(shear)};
}

} // namespace slides
