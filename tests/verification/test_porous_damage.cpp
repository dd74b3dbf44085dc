// ctest-labels: erosion
// The porous layer's moduli and the damage-equivalent stress (the reference's Section 5.2.2–5.2.3):
//  - Hashin–Shtrikman bounds (Eq. 5.1–5.2) against their limits: all of phase 2 gives phase 2,
//    equal phases make the bounds coincide, the bounds are ordered; for voids (C → 0) the upper
//    bounds are the published porous limits κ⁺ = 4κµ(1 − p)/(4µ + 3pκ),
//    µ⁺ = µ(1 − p)(9κ + 8µ)/(9κ + 8µ + 6p(κ + 2µ)) (Torquato, Random Heterogeneous Materials
//    (2002) Eq. 21.24–21.25), and the lower bounds vanish;
//  - Eq. 5.3: porosity 0 gives the matrix; the estimate falls with porosity, lies between the
//    bounds, and changes by less than 0.5 % when C goes from 1e-4 to 1e-6 (the reference's remark:
//    the lower bound, O(C/p) of the matrix, is all that moves);
//  - Eq. 5.4–5.5: R_ν = 1 under uniaxial stress (σ_eq = σ), σ_eq = σ_vm √(2(1 + ν)/3) in shear,
//    and σ_eq²/(2E) equals the elastic strain energy density ½ σ:ε of any stress;
//  - Eq. 5.6: Σ = 0 up to the threshold, (σ_eq − σ₀)/σ₀ beyond.
#include "slides/physics/damage_stress.h"
#include "slides/physics/porous_moduli.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slides {
namespace {

// Table 5.1: bulk modulus 100 GPa, Poisson's ratio 0.3.
constexpr double bulk = 100e9, poisson = 0.3;
const IsotropicModuli matrix{bulk, 3 * bulk*(1 - 2 * poisson) / (2 * (1 + poisson))};

TEST(PorousModuli, HashinShtrikmanBoundsMeetTheirLimits) {
    const IsotropicModuli soft{20e9, 10e9};
    const ModulusBounds allStiff = hashinShtrikmanBulk(soft, matrix, 1.0);
    EXPECT_NEAR(allStiff.lower, matrix.bulk, 1e-12 * bulk);
    EXPECT_NEAR(allStiff.upper, matrix.bulk, 1e-12 * bulk);
    for (const double fraction : {0.0, 0.3, 0.7, 1.0}) {
        const ModulusBounds b = hashinShtrikmanBulk(matrix, matrix, fraction);
        const ModulusBounds s = hashinShtrikmanShear(matrix, matrix, fraction);
        EXPECT_DOUBLE_EQ(b.lower, matrix.bulk);
        EXPECT_DOUBLE_EQ(b.upper, matrix.bulk);
        EXPECT_DOUBLE_EQ(s.lower, matrix.shear);
        EXPECT_DOUBLE_EQ(s.upper, matrix.shear);
        const ModulusBounds mixed = hashinShtrikmanShear(soft, matrix, fraction);
        EXPECT_LE(mixed.lower, mixed.upper * (1 + 1e-15));
        EXPECT_GE(mixed.lower, soft.shear * (1 - 1e-15));
        EXPECT_LE(mixed.upper, matrix.shear * (1 + 1e-15));
    }
}

TEST(PorousModuli, VoidsGiveThePublishedPorousBounds) {
    const double k = matrix.bulk, g = matrix.shear;
    const IsotropicModuli voids{1e-12 * k, 1e-12 * g};
    for (const double p : {0.1, 0.25, 0.4}) {
        const ModulusBounds b = hashinShtrikmanBulk(voids, matrix, 1 - p);
        const ModulusBounds s = hashinShtrikmanShear(voids, matrix, 1 - p);
        EXPECT_NEAR(b.upper, 4 * k * g * (1 - p) / (4 * g + 3 * p * k), 1e-9 * k);
        EXPECT_NEAR(s.upper, g * (1 - p) * (9 * k + 8 * g) / (9 * k + 8 * g + 6 * p * (k + 2 * g)),
                    1e-9 * g);
        EXPECT_LT(b.lower, 1e-9 * k);
        EXPECT_LT(s.lower, 1e-9 * g);
    }
}

TEST(PorousModuli, ConvexCombinationFallsWithPorosityAndIsInsensitiveToThePoreStiffness) {
    const IsotropicModuli solid = porousModuli(matrix, 0.0, 0.5);
    EXPECT_NEAR(solid.bulk, matrix.bulk, 1e-12 * bulk);
    EXPECT_NEAR(solid.shear, matrix.shear, 1e-12 * bulk);
    double previous = matrix.bulk;
    for (const double p : {0.1, 0.2, 0.3, 0.4}) {
        const IsotropicModuli m = porousModuli(matrix, p, 0.5);
        const IsotropicModuli pores{poreStiffnessRatio * matrix.bulk,
                                    poreStiffnessRatio * matrix.shear};
        const ModulusBounds b = hashinShtrikmanBulk(pores, matrix, 1 - p);
        EXPECT_LT(m.bulk, previous);
        EXPECT_GT(m.bulk, b.lower);
        EXPECT_LT(m.bulk, b.upper);
        EXPECT_DOUBLE_EQ(porousModuli(matrix, p, 1.0).bulk, b.upper);
        const IsotropicModuli stiffer = porousModuli(matrix, p, 0.5, 1e-6);
        EXPECT_NEAR(stiffer.bulk / m.bulk, 1.0, 5e-3);
        EXPECT_NEAR(stiffer.shear / m.shear, 1.0, 5e-3);
        previous = m.bulk;
    }
}

TEST(DamageStress, EquivalentStressOfTheClassicalStates) {
    const double sigma = 3e8;
    const Mat3 uniaxial = sigma * Vec3::UnitX() * Vec3::UnitX().transpose();
    EXPECT_NEAR(vonMisesStress(uniaxial), sigma, 1e-9 * sigma);
    EXPECT_NEAR(
        triaxialityFunction(dilatationalStress(uniaxial), vonMisesStress(uniaxial), poisson), 1.0,
        1e-14);
    EXPECT_NEAR(equivalentStress(uniaxial, poisson), sigma, 1e-9 * sigma);
    Mat3 shear = Mat3::Zero();
    shear(0, 1) = shear(1, 0) = sigma;
    EXPECT_NEAR(equivalentStress(shear, poisson),
                vonMisesStress(shear) * std::sqrt(2 * (1 + poisson) / 3), 1e-9 * sigma);
    const Mat3 hydrostatic = -sigma * Mat3::Identity();
    EXPECT_NEAR(equivalentStress(hydrostatic, poisson), sigma * std::sqrt(3 * (1 - 2 * poisson)),
                1e-9 * sigma);
}

TEST(DamageStress, EquivalentStressIsTheElasticEnergyDensity) {
    // ε = (1 + ν)/E σ − ν/E tr σ I; W = ½ σ:ε = σ_eq²/(2E) (Lemaitre & Desmorat Eq. 1.107).
    const double young = 9 * matrix.bulk * matrix.shear / (3 * matrix.bulk + matrix.shear);
    Mat3 stress;
    stress << 2e8, -4e7, 1e8, -4e7, -3e8, 6e7, 1e8, 6e7, 5e7;
    const Mat3 strain =
        (1 + poisson) / young * stress - poisson / young * stress.trace() * Mat3::Identity();
    const double energy = 0.5 * (stress.array() * strain.array()).sum();
    const double equivalent = equivalentStress(stress, poisson);
    EXPECT_NEAR(equivalent * equivalent / (2 * young), energy, 1e-12 * energy);
    EXPECT_NEAR(equivalent,
                vonMisesStress(stress) *
                    std::sqrt(triaxialityFunction(dilatationalStress(stress),
                                                  vonMisesStress(stress), poisson)),
                1e-9 * equivalent);
}

TEST(DamageStress, IndicatorIsZeroUpToTheThreshold) {
    const double threshold = 5e8;
    EXPECT_EQ(damageIndicator(0.0, threshold), 0.0);
    EXPECT_EQ(damageIndicator(threshold, threshold), 0.0);
    EXPECT_DOUBLE_EQ(damageIndicator(7.5e8, threshold), 0.5);
}

} // namespace
} // namespace slides
