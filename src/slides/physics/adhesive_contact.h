// Adhesive contacts of Section 2.6: van der Waals attraction of rigid spheres (Hamaker), the
// Hamaker constant from Lifshitz theory and its combining rules, and the deformable adhesive
// contacts of JKR and DMT with Tabor's parameter choosing between them.
//
// Reference: Section 2.6 of the reference.
//   Hamaker (Eq. 2.69–2.71; Hamaker 1937): spheres R₁, R₂ at centre distance r = R₁ + R₂ + d,
//     p = r² − (R₁ + R₂)², q = r² − (R₁ − R₂)²: U = −A/6 [2R₁R₂/p + 2R₁R₂/q + ln(p/q)], attraction
//     F = dU/dr = 32 A R₁³R₂³ r / (3 p² q²); a sphere at gap d from a plane (R₂ → ∞):
//     U = −A/6 [R/d + R/(d + 2R) + ln(d/(d + 2R))], F = 2AR³/(3 d² (d + 2R)²); both → A R*/(6d²)
//     (Derjaguin, Eq. 2.72) as d → 0.
//   Lifshitz (Eq. 2.81; Israelachvili, Intermolecular and Surface Forces, 3rd ed., Eq. 13.15):
//     A₁₃₂ = 3/4 kT (ε₁−ε₃)/(ε₁+ε₃) (ε₂−ε₃)/(ε₂+ε₃) + 3hν_e/(8√2) (n₁²−n₃²)(n₂²−n₃²) /
//     (√(n₁²+n₃²) √(n₂²+n₃²) [√(n₁²+n₃²) + √(n₂²+n₃²)]); combining rules (Israelachvili
//     §13.6): A₁₂ ≈ √(A₁₁A₂₂), A₁₃₂ ≈ (√A₁₁ − √A₃₃)(√A₂₂ − √A₃₃).
//   JKR (Eq. 2.82–2.86; Johnson, Kendall & Roberts 1971), work of adhesion W, K = 4/3 E*:
//     a³ = R/K [F + 3πWR + √(6πWRF + (3πWR)²)], δ = a²/R − √(2πWa/E*),
//     F(a) = K a³/R − √(8πWE* a³); pull-off under load control −3/2 πWR at a₀/4^{1/3}; under
//     displacement control the contact holds down to a = a₀/6^{2/3}, δ_c = −3/4 (π²W²R/E*²)^{1/3}
//     (a negative overlap: the hysteresis of Fig. 2.5).
//   DMT (Eq. 2.87–2.91 for small deformations; Derjaguin, Muller & Toporov 1975): Hertz's profile
//     with the surface force 2πWR outside it: F = K a³/R − 2πWR, δ = a²/R; pull-off −2πWR.
//   Tabor (Eq. 2.92, with the work of adhesion for Δγ): μ_T = (R W² / (E*² ε₀³))^{1/3}; Johnson &
//     Greenwood's map (1997, J. Colloid Interface Sci. 192:326) puts DMT at μ_T ≲ 0.1, JKR at
//     μ_T ≳ 5, Maugis' transition between: here μ_T ≥ 1 takes JKR, below DMT.
// R is the pair's effective radius R*, E* its effective modulus (physics/contact_pair.h).
//
//     deposition { adhesion taborMap; adhesionFactor 1; contactSeparation 4e-10; }
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>

namespace slides {

/// p = r² − (R₁ + R₂)² = d (2R₁ + 2R₂ + d) and q = r² − (R₁ − R₂)² = (2R₁ + d)(2R₂ + d) of
/// Eq. 2.71 from the gap d = r − R₁ − R₂, free of the cancellation of large radii.
struct HamakerDistances {
    double p, q;
};
inline HamakerDistances hamakerDistances(double radius1, double radius2, double gap) {
    return {gap * (2 * radius1 + 2 * radius2 + gap), (2 * radius1 + gap) * (2 * radius2 + gap)};
}

/// Hamaker energy [J] of spheres R₁, R₂ at gap d > 0 between their surfaces (Eq. 2.71).
inline double hamakerSphereSphereEnergy(double hamakerConstant, double radius1, double radius2,
                                        double gap) {
    const auto [p, q] = hamakerDistances(radius1, radius2, gap);
    const double product = 2 * radius1 * radius2;
    return -hamakerConstant / 6 * (product / p + product / q + std::log(p / q));
}

/// Hamaker attraction [N] of spheres R₁, R₂ at gap d: dU/dr of Eq. 2.71, r = R₁ + R₂ + d.
inline double hamakerSphereSphereForce(double hamakerConstant, double radius1, double radius2,
                                       double gap) {
    const auto [p, q] = hamakerDistances(radius1, radius2, gap);
    const double cubes = std::pow(radius1 * radius2, 3);
    return 32 * hamakerConstant * cubes * (radius1 + radius2 + gap) / (3 * p * p * q * q);
}

/// Hamaker energy [J] of a sphere R at gap d from a half-space (Eq. 2.71 as R₂ → ∞).
inline double hamakerSpherePlaneEnergy(double hamakerConstant, double radius, double gap) {
    return -hamakerConstant / 6 *
           (radius / gap + radius / (gap + 2 * radius) + std::log(gap / (gap + 2 * radius)));
}

/// Hamaker attraction [N] of a sphere R at gap d from a half-space, 2AR³/(3d²(d + 2R)²).
inline double hamakerSpherePlaneForce(double hamakerConstant, double radius, double gap) {
    const double far = gap + 2 * radius;
    return 2 * hamakerConstant * radius * radius * radius / (3 * gap * gap * far * far);
}

/// The dielectric and optical data of a medium for Lifshitz's Hamaker constant.
struct DielectricMedium {
    double permittivity = 1;    ///< static dielectric constant ε
    double refractiveIndex = 1; ///< n in the visible
};

/// Hamaker constant A₁₃₂ [J] of bodies 1 and 2 across medium 3 (Eq. 2.81) at temperature T [K],
/// with the main electronic absorption frequency ν_e [Hz] (≈ 3e15 Hz).
inline double lifshitzHamakerConstant(const DielectricMedium& body1, const DielectricMedium& body2,
                                      const DielectricMedium& medium, double temperature,
                                      double absorptionFrequency = 3.0e15) {
    constexpr double boltzmann = 1.380649e-23; // [J/K]
    constexpr double planck = 6.62607015e-34;  // [J s]
    const auto contrast = [&](const DielectricMedium& body) {
        return (body.permittivity - medium.permittivity) /
               (body.permittivity + medium.permittivity);
    };
    const double zeroFrequency = 0.75 * boltzmann * temperature * contrast(body1) * contrast(body2);
    const double n1 = body1.refractiveIndex * body1.refractiveIndex;
    const double n2 = body2.refractiveIndex * body2.refractiveIndex;
    const double n3 = medium.refractiveIndex * medium.refractiveIndex;
    const double root1 = std::sqrt(n1 + n3), root2 = std::sqrt(n2 + n3);
    const double dispersion = 3 * planck * absorptionFrequency / (8 * std::numbers::sqrt2) *
                              (n1 - n3) * (n2 - n3) / (root1 * root2 * (root1 + root2));
    return zeroFrequency + dispersion;
}

/// A₁₂ ≈ √(A₁₁ A₂₂) of two materials from their own constants in vacuum (combining rule).
inline double combinedHamakerConstant(double constant11, double constant22) {
    return std::sqrt(constant11 * constant22);
}

/// A₁₃₂ ≈ (√A₁₁ − √A₃₃)(√A₂₂ − √A₃₃) across a medium 3 (combining rule; negative: repulsion).
inline double combinedHamakerConstant(double constant11, double constant22, double constant33) {
    return (std::sqrt(constant11) - std::sqrt(constant33)) *
           (std::sqrt(constant22) - std::sqrt(constant33));
}

/// Tabor's parameter μ_T = (R W² / (E*² ε₀³))^{1/3} (Eq. 2.92).
inline double taborParameter(double radius, double workOfAdhesion, double youngsModulus,
                             double separation) {
    return std::cbrt(radius * workOfAdhesion * workOfAdhesion /
                     (youngsModulus * youngsModulus * separation * separation * separation));
}

/// Whether Tabor's parameter puts a contact in the JKR regime (μ_T ≥ 1) rather than DMT's.
inline bool taborSelectsJkr(double taborParameter) { return taborParameter >= 1.0; }

/// JKR pull-off force −3/2 πWR [N] (Eq. 2.84).
inline double jkrPullOffForce(double radius, double workOfAdhesion) {
    return -1.5 * std::numbers::pi * workOfAdhesion * radius;
}

/// DMT pull-off force −2πWR [N] (Eq. 2.72, 2.91 for small deformations).
inline double dmtPullOffForce(double radius, double workOfAdhesion) {
    return -2 * std::numbers::pi * workOfAdhesion * radius;
}

/// JKR contact radius [m] under load F ≥ −3/2 πWR (Eq. 2.82).
inline double jkrContactRadius(double load, double radius, double workOfAdhesion,
                               double youngsModulus) {
    const double adhesion = 3 * std::numbers::pi * workOfAdhesion * radius;
    const double root = std::sqrt(std::max(0.0, 2 * adhesion * load + adhesion * adhesion));
    return std::cbrt(3 * radius / (4 * youngsModulus) * (load + adhesion + root));
}

/// JKR contact radius a₀ [m] at zero load (Eq. 2.83).
inline double jkrZeroLoadRadius(double radius, double workOfAdhesion, double youngsModulus) {
    return std::cbrt(4.5 * std::numbers::pi * workOfAdhesion * radius * radius / youngsModulus);
}

/// JKR overlap δ(a) = a²/R − √(2πWa/E*) [m] (Eq. 2.86).
inline double jkrOverlap(double contactRadius, double radius, double workOfAdhesion,
                         double youngsModulus) {
    return contactRadius * contactRadius / radius -
           std::sqrt(2 * std::numbers::pi * workOfAdhesion * contactRadius / youngsModulus);
}

/// JKR load F(a) = 4E*a³/(3R) − √(8πWE*a³) [N].
inline double jkrLoad(double contactRadius, double radius, double workOfAdhesion,
                      double youngsModulus) {
    const double cube = contactRadius * contactRadius * contactRadius;
    return 4 * youngsModulus * cube / (3 * radius) -
           std::sqrt(8 * std::numbers::pi * workOfAdhesion * youngsModulus * cube);
}

/// The overlap at which a JKR contact parts under displacement control, δ_c < 0, where
/// dδ/da = 0 at a = a₀/6^{2/3}.
inline double jkrSeparationOverlap(double radius, double workOfAdhesion, double youngsModulus) {
    const double contactRadius =
        jkrZeroLoadRadius(radius, workOfAdhesion, youngsModulus) / std::cbrt(36.0);
    return jkrOverlap(contactRadius, radius, workOfAdhesion, youngsModulus);
}

/// DMT contact radius [m] under load F ≥ −2πWR: Hertz's under F + 2πWR.
inline double dmtContactRadius(double load, double radius, double workOfAdhesion,
                               double youngsModulus) {
    return std::cbrt(3 * radius / (4 * youngsModulus) *
                     (load + 2 * std::numbers::pi * workOfAdhesion * radius));
}

} // namespace slides
