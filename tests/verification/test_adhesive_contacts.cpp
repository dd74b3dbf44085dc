// ctest-labels: adhesion
// Adhesive contacts of Section 2.6 (physics/adhesive_contact.h) against their closed forms:
//  - Hamaker sphere–plane energy against the pair integral of Eq. 2.69 (the sphere cut into
//    slices, each attracted by the half-space as −πCρ/(6z³)), integrated numerically; the
//    sphere–sphere force is the derivative of its energy (Eq. 2.71), tends to the sphere–plane
//    one as R₂ → ∞ and to Derjaguin's A R*/(6d²) (Eq. 2.72) as d → 0;
//  - Lifshitz's Hamaker constant (Eq. 2.81) of water across vacuum: 3.7e-20 J in Israelachvili's
//    Table 13.2 (ε = 80, n = 1.333, ν_e = 3.0e15 Hz); the combining rules of Section 2.6.2;
//  - JKR (Eq. 2.82–2.86): the least load of F(a) is the pull-off −3/2 πWR, reached at a₀/4^{1/3};
//    load and contact radius invert each other; the least overlap of δ(a) is the separation
//    overlap −3/4 (π²W²R/E*²)^{1/3} < 0 (hysteresis); W = 0 gives Hertz's a³ = 3RF/(4E*);
//  - DMT: pull-off −2πWR, Hertz's contact radius under F + 2πWR; Tabor's parameter (Eq. 2.92)
//    choosing between them for Eq. 5.9's adhesion force (deposition.adhesion taborMap).
// All to 1e-6 (the numerical minimisations and integrals are converged well below that).
#include "slides/physics/adhesion.h"
#include "slides/physics/adhesive_contact.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>

namespace slides {
namespace {

constexpr double pi = std::numbers::pi;

/// ∫ f over [a, b] by composite Simpson with n (even) intervals.
double simpson(const std::function<double(double)>& f, double a, double b, int n) {
    const double h = (b - a) / n;
    double sum = f(a) + f(b);
    for (int k = 1; k < n; ++k) sum += (k % 2 == 1 ? 4 : 2) * f(a + k * h);
    return sum * h / 3;
}

/// The x in [a, b] where the unimodal f is least, by golden-section search to 1e-15 of b − a.
double argMin(const std::function<double(double)>& f, double a, double b) {
    const double ratio = (std::sqrt(5.0) - 1) / 2;
    double c = b - ratio * (b - a), d = a + ratio * (b - a);
    while (b - a > 1e-15 * (std::abs(a) + std::abs(b))) {
        if (f(c) < f(d))
            b = d;
        else
            a = c;
        c = b - ratio * (b - a);
        d = a + ratio * (b - a);
    }
    return 0.5 * (a + b);
}

TEST(Hamaker, SpherePlaneEnergyIsThePairIntegralOfEquation269) {
    // A slice of the sphere at height s above its lowest point has area π(2Rs − s²) and lies
    // d + s from the plane: U = −A/6 ∫₀^{2R} (2Rs − s²)/(d + s)³ ds with A = π²Cρ₁ρ₂. The
    // integrand peaks at s ≈ d: integrate over t = ln(1 + s/d).
    const double hamaker = 1e-19, radius = 1e-6;
    for (const double gap : {1e-9, 1e-7, 1e-6, 1e-5}) {
        const auto integrand = [&](double t) {
            const double s = gap * std::expm1(t);
            return (2 * radius * s - s * s) / std::pow(gap + s, 3) * gap * std::exp(t);
        };
        const double integral =
            -hamaker / 6 * simpson(integrand, 0, std::log1p(2 * radius / gap), 20000);
        EXPECT_NEAR(hamakerSpherePlaneEnergy(hamaker, radius, gap) / integral, 1.0, 1e-6) << gap;
    }
}

TEST(Hamaker, SphereSphereForceIsTheEnergysSlopeAndTendsToItsLimits) {
    const double hamaker = 1e-19, radius1 = 1e-6, radius2 = 2.5e-6;
    const double effective = radius1 * radius2 / (radius1 + radius2);
    for (const double gap : {1e-9, 1e-7, 1e-6}) {
        const double h = 1e-4 * gap;
        const double slope = (hamakerSphereSphereEnergy(hamaker, radius1, radius2, gap + h) -
                              hamakerSphereSphereEnergy(hamaker, radius1, radius2, gap - h)) /
                             (2 * h);
        EXPECT_NEAR(hamakerSphereSphereForce(hamaker, radius1, radius2, gap) / slope, 1.0, 1e-6);
        // The sphere–plane force as the second sphere grows (relative change ~ R₁/R₂ = 1e-8).
        const double huge = 100;
        EXPECT_NEAR(hamakerSphereSphereForce(hamaker, radius1, huge, gap) /
                        hamakerSpherePlaneForce(hamaker, radius1, gap),
                    1.0, 1e-6);
        const double planeSlope = (hamakerSpherePlaneEnergy(hamaker, radius1, gap + h) -
                                   hamakerSpherePlaneEnergy(hamaker, radius1, gap - h)) /
                                  (2 * h);
        EXPECT_NEAR(hamakerSpherePlaneForce(hamaker, radius1, gap) / planeSlope, 1.0, 1e-6);
    }
    // Derjaguin (Eq. 2.72): A R*/(6d²) as d → 0, the relative correction of order d/R.
    const double gap = 1e-14;
    EXPECT_NEAR(hamakerSphereSphereForce(hamaker, radius1, radius2, gap) /
                    (hamaker * effective / (6 * gap * gap)),
                1.0, 1e-6);
}

TEST(Hamaker, LifshitzConstantOfWaterAndTheCombiningRules) {
    const DielectricMedium water{80, 1.333}, vacuum{1, 1};
    const double waterAcrossVacuum = lifshitzHamakerConstant(water, water, vacuum, 293, 3.0e15);
    // Israelachvili's Table 13.2 gives 3.7e-20 J to two digits.
    EXPECT_NEAR(waterAcrossVacuum, 3.7e-20, 0.05e-20);
    const DielectricMedium quartz{4.5, 1.544};
    EXPECT_DOUBLE_EQ(lifshitzHamakerConstant(water, quartz, vacuum, 293),
                     lifshitzHamakerConstant(quartz, water, vacuum, 293));
    // Across a medium like one of the bodies there is no attraction; unlike ones attract.
    EXPECT_NEAR(lifshitzHamakerConstant(water, quartz, water, 293), 0.0, 1e-35);
    EXPECT_GT(lifshitzHamakerConstant(quartz, quartz, water, 293), 0.0);
    // Combining rules: the geometric mean; across a medium 3, (√A₁₁ − √A₃₃)(√A₂₂ − √A₃₃):
    // zero for 3 = 1, (√A₁₁ − √A₃₃)² ≥ 0 for 1 = 2, negative (repulsion) for A₁₁ < A₃₃ < A₂₂.
    EXPECT_DOUBLE_EQ(combinedHamakerConstant(1e-19, 4e-19), 2e-19);
    EXPECT_DOUBLE_EQ(combinedHamakerConstant(1e-19, 4e-19, 0), 2e-19);
    EXPECT_NEAR(combinedHamakerConstant(1e-19, 4e-19, 1e-19), 0.0, 1e-35);
    EXPECT_NEAR(combinedHamakerConstant(4e-19, 4e-19, 1e-19), 1e-19, 1e-30);
    EXPECT_LT(combinedHamakerConstant(1e-19, 9e-19, 4e-19), 0.0);
}

// A 10 µm polystyrene-like sphere pair: R* = 5 µm, E* = 2 GPa, W = 0.06 J/m².
constexpr double radius = 5e-6, modulus = 2e9, work = 0.06;

TEST(JkrContact, PullOffIsTheLeastLoadAtAQuarterCubeRootOfTheZeroLoadRadius) {
    const double zeroLoad = jkrZeroLoadRadius(radius, work, modulus);
    EXPECT_NEAR(jkrContactRadius(0, radius, work, modulus) / zeroLoad, 1.0, 1e-12);
    const auto load = [&](double a) { return jkrLoad(a, radius, work, modulus); };
    const double least = argMin(load, 1e-3 * zeroLoad, zeroLoad);
    const double pullOff = jkrPullOffForce(radius, work);
    EXPECT_NEAR(pullOff / (-1.5 * pi * work * radius), 1.0, 1e-15); // Eq. 2.84
    EXPECT_NEAR(load(least) / pullOff, 1.0, 1e-6);
    EXPECT_NEAR(least / (zeroLoad / std::cbrt(4.0)), 1.0, 1e-6); // Eq. 2.85
    EXPECT_NEAR(jkrContactRadius(pullOff, radius, work, modulus) / least, 1.0, 1e-6);
}

TEST(JkrContact, ContactRadiusAgainstLoadAndOverlapInvertEachOther) {
    const double scale = pi * work * radius;
    for (const double load : {-1.2 * scale, -0.5 * scale, 0.0, 3 * scale, 100 * scale}) {
        const double a = jkrContactRadius(load, radius, work, modulus);
        EXPECT_NEAR(jkrLoad(a, radius, work, modulus), load, 1e-6 * scale) << load / scale;
    }
    // Eq. 2.86 as printed: δ = a²/R [1 − 2/3 (a₀/a)^{3/2}].
    const double zeroLoad = jkrZeroLoadRadius(radius, work, modulus);
    for (const double a : {0.3 * zeroLoad, zeroLoad, 4 * zeroLoad}) {
        const double printed = a * a / radius * (1 - 2.0 / 3.0 * std::pow(zeroLoad / a, 1.5));
        EXPECT_NEAR(jkrOverlap(a, radius, work, modulus) / printed, 1.0, 1e-12);
    }
    // Without adhesion, Hertz: a³ = 3RF/(4E*), δ = a²/R.
    const double hertz = jkrContactRadius(1e-3, radius, 0, modulus);
    EXPECT_NEAR(hertz / std::cbrt(3 * radius * 1e-3 / (4 * modulus)), 1.0, 1e-12);
    EXPECT_NEAR(jkrOverlap(hertz, radius, 0, modulus) / (hertz * hertz / radius), 1.0, 1e-12);
}

TEST(JkrContact, PartsAtANegativeOverlapUnderDisplacementControl) {
    const double zeroLoad = jkrZeroLoadRadius(radius, work, modulus);
    const auto overlap = [&](double a) { return jkrOverlap(a, radius, work, modulus); };
    const double least = argMin(overlap, 1e-4 * zeroLoad, zeroLoad);
    const double separation = jkrSeparationOverlap(radius, work, modulus);
    EXPECT_LT(separation, 0.0);
    EXPECT_NEAR(overlap(least) / separation, 1.0, 1e-6);
    EXPECT_NEAR(separation /
                    (-0.75 * std::cbrt(pi * pi * work * work * radius / (modulus * modulus))),
                1.0, 1e-12);
    // The load there is tensile, and smaller than the pull-off of load control.
    const double load = jkrLoad(least, radius, work, modulus);
    EXPECT_LT(load, 0.0);
    EXPECT_GT(load, jkrPullOffForce(radius, work));
}

TEST(DmtContact, PullOffAndContactRadiusOfHertzUnderTheShiftedLoad) {
    EXPECT_NEAR(dmtPullOffForce(radius, work) / (-2 * pi * work * radius), 1.0, 1e-15);
    EXPECT_NEAR(dmtContactRadius(dmtPullOffForce(radius, work), radius, work, modulus), 0.0, 1e-15);
    const double load = 1e-5;
    const double a = dmtContactRadius(load, radius, work, modulus);
    EXPECT_NEAR(4 * modulus * a * a * a / (3 * radius) - 2 * pi * work * radius, load, 1e-6 * load);
}

TEST(TaborParameter, ChoosesJkrForSoftLargeSpheresAndDmtForStiffSmallOnes) {
    // μ_T = (R W²/(E*² ε₀³))^{1/3}: 5 µm polystyrene (2 GPa) against 50 nm alumina (200 GPa).
    const double separation = 4e-10;
    const double soft = taborParameter(radius, work, modulus, separation);
    const double stiff = taborParameter(50e-9, work, 200e9, separation);
    EXPECT_NEAR(soft, std::cbrt(radius * work * work / (modulus * modulus * 6.4e-29)), 1e-12);
    EXPECT_GT(soft, 1.0);
    EXPECT_LT(stiff, 0.1);
    // Eq. 5.9's adhesion force by name: JKR's 3/2 πWR* for the soft pair, DMT's 2πWR* for the
    // stiff one.
    AdhesionSettings settings{AdhesionModel::taborMap, 1.0, 0.0, separation};
    ContactPair pair;
    pair.workOfAdhesion = work;
    pair.radius = radius;
    pair.youngsModulus = modulus;
    EXPECT_NEAR(adhesionForce(settings, pair), 1.5 * pi * work * radius, 1e-18);
    settings.model = AdhesionModel::jkr;
    EXPECT_NEAR(adhesionForce(settings, pair), 1.5 * pi * work * radius, 1e-18);
    pair.radius = 50e-9;
    pair.youngsModulus = 200e9;
    settings.model = AdhesionModel::taborMap;
    EXPECT_NEAR(adhesionForce(settings, pair), 2 * pi * work * 50e-9, 1e-20);
    settings.model = AdhesionModel::dmt;
    EXPECT_NEAR(adhesionForce(settings, pair), 2 * pi * work * 50e-9, 1e-20);
}

} // namespace
} // namespace slides
