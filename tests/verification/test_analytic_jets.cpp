// ctest-labels: foundation carrier
// The analytic carriers against their closed forms: Bickley's plane jet (Eq. 5.10/5.11;
// Schlichting, Boundary-Layer Theory) — continuity, centreline decay ∝ s^(−1/3), spreading
// ∝ s^(2/3), conserved momentum flux, Schlichting's coefficients — its axisymmetric use, and
// Schlichting's round laminar jet (continuity in cylindrical coordinates, momentum flux,
// decay ∝ 1/s). Analytic gradients are checked against central differences everywhere.
#include "slides/carrier/analytic_jet.h"
#include "slides/carrier/round_laminar_jet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace slides {
namespace {

NozzleSettings nozzle() {
    NozzleSettings n;
    n.centre = Vec3(0.01, -0.02, 0.005);
    n.axis = Vec3(1, 2, 2) / 3.0; // oblique, so no component is special
    n.radius = 2e-3;
    n.crossSpanDirection = Vec3(2, -2, 1) / 3.0; // ⟂ axis
    return n;
}

CarrierSettings jet(JetProfileKind profile, double coreLength = 8e-3) {
    CarrierSettings c;
    c.type = CarrierType::analyticJet;
    c.profile = profile;
    c.nozzleVelocity = 25;
    c.coreLength = coreLength;
    c.viscosity = 1.4e-3;
    return c;
}

Vec3 sampleU(const CarrierField& field, const Vec3& point) {
    CarrierSample out;
    field.sample(std::span(&point, 1), 0.0, {}, out);
    return out.velocity[0];
}

Mat3 sampleGradient(const CarrierField& field, const Vec3& point) {
    CarrierSample out;
    field.sample(std::span(&point, 1), 0.0, {true}, out);
    return out.velocityGradient[0];
}

/// Central differences of U with step h: error O(h²|∂³U|).
Mat3 differenceGradient(const CarrierField& field, const Vec3& point, double h) {
    Mat3 gradient;
    for (int j = 0; j < 3; ++j) {
        const Vec3 step = h * Vec3::Unit(j);
        gradient.col(j) = (sampleU(field, point + step) - sampleU(field, point - step)) / (2 * h);
    }
    return gradient;
}

/// A point at axial distance a, cross-span y along e_y and z along e_a × e_y.
Vec3 at(double a, double y, double z = 0) {
    const NozzleSettings n = nozzle();
    return n.centre + a * n.axis + y * n.crossSpanDirection + z * n.axis.cross(n.crossSpanDirection);
}

TEST(BickleyJet, SchlichtingCoefficients) {
    // With K = ν = 1 the coefficients are Schlichting's decimals: 0.4543, 0.2752, 0.5503.
    NozzleSettings unit = nozzle();
    unit.radius = 0.5;
    CarrierSettings settings = jet(JetProfileKind::planar);
    settings.nozzleVelocity = 1; // K = 2 R U0² = 1
    settings.viscosity = 1;
    const AnalyticJet field(unit, settings);
    EXPECT_NEAR(field.profile().C1, 0.4543, 5e-5);
    EXPECT_NEAR(field.profile().C3, 0.2752, 5e-5);
    EXPECT_NEAR(field.profile().C2, 0.5503, 5e-5);
}

TEST(BickleyJet, PlanarFieldIsDivergenceFree) {
    // ∇·u = ∂u/∂s + ∂v/∂y = 0 for Eq. 5.10/5.11 with C2 = C1/(3C3). Central differences with
    // h = 1e-6 m carry a truncation error ~h²|∂³u| ≈ 1e-6 of the velocity-gradient scale.
    const AnalyticJet field(nozzle(), jet(JetProfileKind::planar));
    double largest = 0;
    for (double a : {0.012, 0.03, 0.06, 0.2})
        for (double y : {0.0, 5e-4, 2e-3, 6e-3, 2e-2}) {
            const Mat3 numeric = differenceGradient(field, at(a, y, 3e-3), 1e-6);
            largest = std::max(largest, numeric.norm());
            EXPECT_NEAR(numeric.trace(), 0.0, 1e-6 * numeric.norm() + 1e-9)
                << "a = " << a << ", y = " << y;
        }
    EXPECT_GT(largest, 100.0) << "the test must probe a sheared field";
}

TEST(BickleyJet, CentrelineDecaysAsCubeRootAndWidthGrowsAsTwoThirds) {
    // u_c = C1 s^(−1/3) and the half-velocity width y½ = arcsech(√½)·s^(2/3)/C3.
    const AnalyticJet field(nozzle(), jet(JetProfileKind::planar));
    const double s0 = field.virtualOrigin();
    const double halfWidthEta = std::acosh(std::sqrt(2.0)); // sech²η = 1/2
    for (double a : {0.01, 0.05, 0.2, 1.0}) {
        const double s = a - 8e-3 + s0;
        const double centre = sampleU(field, at(a, 0)).dot(nozzle().axis);
        EXPECT_NEAR(centre * std::cbrt(s), field.profile().C1, 1e-12 * field.profile().C1);
        const double halfWidth = halfWidthEta * std::cbrt(s * s) / field.profile().C3;
        EXPECT_NEAR(sampleU(field, at(a, halfWidth)).dot(nozzle().axis) / centre, 0.5, 1e-12);
    }
}

TEST(BickleyJet, MomentumFluxIsConservedAndEqualsTheNozzles) {
    // ∫u² dy = (4/3) C1² / C3 = K = 2 R U0² at every s (Simpson, 20001 points to |η| = 20).
    const AnalyticJet field(nozzle(), jet(JetProfileKind::planar));
    const double K = 2 * 2e-3 * 25.0 * 25.0;
    for (double a : {0.01, 0.1, 1.0}) {
        const double s = a - 8e-3 + field.virtualOrigin();
        const double span = 20 * std::cbrt(s * s) / field.profile().C3;
        const int n = 20000;
        const double h = 2 * span / n;
        double flux = 0;
        for (int k = 0; k <= n; ++k) {
            const double u = sampleU(field, at(a, -span + k * h)).dot(nozzle().axis);
            flux += (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2)) * u * u;
        }
        EXPECT_NEAR(flux * h / 3 / K, 1.0, 1e-9) << "a = " << a;
    }
}

TEST(BickleyJet, VirtualOriginPutsExitVelocityOnTheCentrelineAtTheCoreEnd) {
    const AnalyticJet field(nozzle(), jet(JetProfileKind::axisymmetric));
    const double axial = nozzle().axis.dot(sampleU(field, at(8e-3 - 1e-12, 0)));
    EXPECT_NEAR(axial, 25.0, 1e-9);
    EXPECT_NEAR(nozzle().axis.dot(sampleU(field, at(8e-3 + 1e-12, 0))), 25.0, 1e-9);
    EXPECT_NEAR(nozzle().axis.dot(sampleU(field, at(1e-3, 0))), 25.0, 1e-12) << "core";
    EXPECT_EQ(sampleU(field, at(-1e-6, 0)), Vec3::Zero()) << "behind the nozzle";
    // In the core there is no entrainment: U is parallel to the axis.
    const Vec3 core = sampleU(field, at(4e-3, 3e-3));
    EXPECT_NEAR((core - core.dot(nozzle().axis) * nozzle().axis).norm(), 0.0, 1e-14);
}

TEST(BickleyJet, EntrainsTowardTheAxis) {
    // Far from the axis v → −C2 s^(−2/3) (tanh η → 1, η sech²η → 0): inflow. At y = 0.1 m,
    // η ≈ 18 and the neglected terms are below 1e-14.
    const AnalyticJet field(nozzle(), jet(JetProfileKind::axisymmetric));
    const Vec3 outward = nozzle().crossSpanDirection;
    const Vec3 u = sampleU(field, at(0.05, 0.1));
    const double s = 0.05 - 8e-3 + field.virtualOrigin();
    const double farField = -field.profile().C2 / std::cbrt(s * s);
    EXPECT_NEAR(u.dot(outward), farField, 1e-12 * std::abs(farField));
    EXPECT_LT(sampleU(field, at(0.05, 0.01)).dot(outward), 0.0);
}

class JetGradient : public ::testing::TestWithParam<int> {};

TEST_P(JetGradient, AnalyticGradientMatchesCentralDifferences) {
    // Every carrier's dU_i/dx_j against central differences (h = 1e-7 m, error ~1e-6 relative)
    // in the core, beyond it, near and on the axis.
    const int kind = GetParam();
    CarrierSettings settings = jet(kind == 0 ? JetProfileKind::planar : JetProfileKind::axisymmetric);
    std::unique_ptr<CarrierField> field;
    if (kind < 2) {
        field = std::make_unique<AnalyticJet>(nozzle(), settings);
    } else {
        settings.viscosity = 2e-4;
        field = std::make_unique<RoundLaminarJet>(nozzle(), settings);
    }
    for (double a : {4e-3, 0.012, 0.05, 0.3})
        for (double y : {0.0, 1e-5, 1e-3, 4e-3, 1.5e-2})
            for (double z : {0.0, 2e-3}) {
                const Vec3 point = at(a, y, z);
                const Mat3 analytic = sampleGradient(*field, point);
                const Mat3 numeric = differenceGradient(*field, point, 1e-7);
                ASSERT_TRUE(analytic.allFinite());
                EXPECT_LT((analytic - numeric).norm(), 2e-6 * analytic.norm() + 1e-6)
                    << "kind " << kind << " a = " << a << " y = " << y << " z = " << z
                    << "\nanalytic\n" << analytic << "\nnumeric\n" << numeric;
            }
}

std::string carrierName(const ::testing::TestParamInfo<int>& info) {
    constexpr const char* names[] = {"planarSech2", "axisymmetricSech2", "roundLaminar"};
    return names[info.param];
}

INSTANTIATE_TEST_SUITE_P(Carriers, JetGradient, ::testing::Values(0, 1, 2), carrierName);

TEST(RoundLaminarJet, SatisfiesContinuityInCylindricalCoordinates) {
    // Schlichting's solution: ∇·U = 0 in 3-D (trace of the analytic gradient, which the test
    // above ties to the field), checked over the developed jet.
    CarrierSettings settings = jet(JetProfileKind::axisymmetric, 0.0);
    settings.viscosity = 2e-4;
    const RoundLaminarJet field(nozzle(), settings);
    for (double a : {0.001, 0.02, 0.2})
        for (double r : {0.0, 2e-4, 1e-3, 5e-3, 3e-2}) {
            const Mat3 gradient = sampleGradient(field, at(a, r, 0.5 * r));
            EXPECT_NEAR(gradient.trace(), 0.0, 1e-10 * gradient.norm()) << a << " " << r;
        }
}

TEST(RoundLaminarJet, MomentumFluxAndCentrelineDecay) {
    // ∫u² 2πr dr = K = πR²U0² at every s; u_c·s = 3K/(8πν). (a = 1e-9 m rather than 0 keeps
    // round-off in the oblique frame from putting points behind the nozzle.)
    CarrierSettings settings = jet(JetProfileKind::axisymmetric, 0.0);
    settings.viscosity = 2e-4;
    const RoundLaminarJet field(nozzle(), settings);
    const double K = field.momentumFlux();
    for (double a : {1e-9, 0.05, 0.5}) {
        const double s = a + field.virtualOrigin();
        const double reach = 400 * s / field.profile().similarity; // u ∝ ξ^(−4): tail < 1e-9
        const int n = 200000;
        const double h = reach / n;
        double flux = 0;
        for (int k = 0; k <= n; ++k) {
            const double r = k * h;
            const double u = nozzle().axis.dot(sampleU(field, at(a, r)));
            flux += (k == 0 || k == n ? 1 : (k % 2 ? 4 : 2)) * u * u * 2 * std::numbers::pi * r;
        }
        EXPECT_NEAR(flux * h / 3 / K, 1.0, 1e-6) << "a = " << a;
        const double centre = nozzle().axis.dot(sampleU(field, at(a, 0)));
        EXPECT_NEAR(centre * s, field.profile().amplitude, 1e-12 * field.profile().amplitude);
    }
    EXPECT_NEAR(nozzle().axis.dot(sampleU(field, at(1e-9, 0))), 25.0, 1e-6); // U0 s0/(s0 + 1e-9)
}

TEST(AnalyticJet, ExplicitCoefficientsAndContinuityOfC2) {
    CarrierSettings settings = jet(JetProfileKind::planar);
    settings.C1 = 7.0;
    settings.C3 = 30.0;
    const AnalyticJet field(nozzle(), settings);
    EXPECT_DOUBLE_EQ(field.profile().C2, 7.0 / 90.0);
    EXPECT_NEAR(field.virtualOrigin(), std::pow(7.0 / 25.0, 3), 1e-15);
    settings.C2 = 0.1;
    EXPECT_THROW(AnalyticJet(nozzle(), settings), std::invalid_argument);
}

} // namespace
} // namespace slides
