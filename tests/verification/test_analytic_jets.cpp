// ctest-labels: foundation carrier
// The analytic carriers against their closed forms and conservation laws: Bickley's plane jet
// (Eq. 5.10/5.11 of the reference; Schlichting, Boundary-Layer Theory, "plane jet"), its
// axisymmetric use (y → r), and Schlichting's round laminar jet ("circular jet"); the shared
// nozzle frame (core, virtual origin, rest behind the exit plane). Analytic gradients are
// checked against central differences everywhere, including on the axis.
#include "slides/carrier/analytic_jet.h"
#include "slides/carrier/round_laminar_jet.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace slides {
namespace {

constexpr double U0 = 25;                 // nozzle exit velocity [m/s]
constexpr double nozzleRadius = 2e-3;     // [m]
constexpr double sech2Viscosity = 1.4e-3; // effective ν of the sech² jet [m²/s]
constexpr double roundViscosity = 2e-4;   // ν of the round laminar jet, Re = U0 R/ν = 250
constexpr double coreLength = 8e-3;       // [m]

JetNozzle nozzle() {
    JetNozzle n;
    n.centre = Vec3(0.01, -0.02, 0.005);
    n.axis = Vec3(1, 2, 2) / 3.0; // oblique, so no Cartesian component is special
    n.radius = nozzleRadius;
    n.crossSpanDirection = Vec3(2, -2, 1) / 3.0; // ⟂ axis
    return n;
}

AnalyticJetParameters sech2(JetGeometry geometry, double core = coreLength) {
    AnalyticJetParameters p;
    p.profile = geometry;
    p.nozzleVelocity = U0;
    p.viscosity = sech2Viscosity;
    p.coreLength = core;
    return p;
}

RoundLaminarJetParameters roundJet(double core = coreLength) {
    return {.nozzleVelocity = U0, .viscosity = roundViscosity, .coreLength = core};
}

/// A point at axial distance a, cross-span y along e_y and z along e_a × e_y.
Vec3 at(double a, double y, double z = 0) {
    const JetNozzle n = nozzle();
    return n.centre + a * n.axis + y * n.crossSpanDirection +
           z * n.axis.cross(n.crossSpanDirection);
}

Vec3 sampleU(const CarrierField& field, const Vec3& point) {
    CarrierSample out;
    field.sample(std::span(&point, 1), 0.0, {}, out);
    return out.velocity[0];
}

Mat3 sampleGradient(const CarrierField& field, const Vec3& point) {
    CarrierSample out;
    field.sample(std::span(&point, 1), 0.0, {.velocityGradient = true}, out);
    return out.velocityGradient[0];
}

double axialU(const CarrierField& field, const Vec3& point) {
    return nozzle().axis.dot(sampleU(field, point));
}

/// Central differences of U, column j = ∂U/∂x_j: truncation (h²/6)|∂³U|, round-off ~ε|U|/h.
Mat3 differenceGradient(const CarrierField& field, const Vec3& point, double h) {
    Mat3 gradient;
    for (int j = 0; j < 3; ++j) {
        const Vec3 step = h * Vec3::Unit(j);
        gradient.col(j) = (sampleU(field, point + step) - sampleU(field, point - step)) / (2 * h);
    }
    return gradient;
}

/// Composite Simpson rule on [lo, hi] with n (even) intervals: error (hi−lo) h⁴ |f''''|/180.
double simpson(const std::function<double(double)>& f, double lo, double hi, int n) {
    const double h = (hi - lo) / n;
    double sum = f(lo) + f(hi);
    for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * f(lo + k * h);
    return sum * h / 3;
}

void measured(const std::string& what, double value) {
    ::testing::Test::RecordProperty(what, std::to_string(value));
    std::cout << "[ measured ] " << what << " = " << value << '\n';
}

// ---------------------------------------------------------------- Bickley's plane jet

TEST(BickleyJet, SchlichtingCoefficients) {
    // C1 = (3K²/(32ν))^(1/3), C3 = (K/(48ν²))^(1/3), C2 = (Kν/6)^(1/3): with K = 2bU0² = 1 and
    // ν = 1 they are Schlichting's decimals 0.4543, 0.2752, 0.5503 (4 digits).
    JetNozzle unit = nozzle();
    unit.radius = 0.5;
    AnalyticJetParameters parameters = sech2(JetGeometry::planar);
    parameters.nozzleVelocity = 1;
    parameters.viscosity = 1;
    const AnalyticJet jet(unit, parameters);
    EXPECT_NEAR(jet.C1(), 0.4543, 5e-5);
    EXPECT_NEAR(jet.C3(), 0.2752, 5e-5);
    EXPECT_NEAR(jet.C2(), 0.5503, 5e-5);
    EXPECT_NEAR(jet.C2(), std::cbrt(1.0 / 6.0), 1e-15); // C1/(3 C3) = (Kν/6)^(1/3)
    EXPECT_NEAR(jet.momentumFlux(), 1.0, 1e-15);        // (4/3) C1²/C3 = K
    measured("C1 - 0.4543", jet.C1() - 0.4543);
    measured("C3 - 0.2752", jet.C3() - 0.2752);
    measured("C2 - 0.5503", jet.C2() - 0.5503);
}

TEST(BickleyJet, PlanarFieldIsDivergenceFree) {
    // ∇·U = ∂u/∂s + ∂v/∂y = 0 (Eq. 5.10/5.11 with C2 = C1/(3 C3)), from central differences of
    // the sampled 3-D field on a grid in the developed jet. The jet width there is
    // w = s^(2/3)/C3 ≥ 3 mm, so with h = 1e-6 m the truncation error of each diagonal entry is
    // ~(h/w)²|∇U| ≈ 1e-7|∇U|, round-off ε|x|/h·|∇U| + ε|U|/h ≈ 1e-9|∇U|: tolerance 1e-6|∇U|.
    const AnalyticJet jet(nozzle(), sech2(JetGeometry::planar));
    double worst = 0;
    double steepest = 0;
    for (double a : {0.012, 0.02, 0.05, 0.1, 0.3, 1.0})
        for (double y : {0.0, 5e-4, -5e-4, 2e-3, 6e-3, -2e-2})
            for (double z : {0.0, 3e-3}) {
                const Mat3 numeric = differenceGradient(jet, at(a, y, z), 1e-6);
                steepest = std::max(steepest, numeric.norm());
                EXPECT_LE(std::abs(numeric.trace()), 1e-6 * numeric.norm())
                    << "a = " << a << ", y = " << y << "\n"
                    << numeric;
                worst = std::max(worst, std::abs(numeric.trace()) / numeric.norm());
            }
    EXPECT_GT(steepest, 1000.0) << "the grid must probe a strongly sheared field [1/s]";
    measured("planar max |div U|/|grad U| (FD)", worst);
}

TEST(BickleyJet, AxisymmetricUseIsNotSolenoidal) {
    // y → r adds the hoop term: ∇·U = ∂u/∂s + ∂v/∂r + v/r = v/r ≠ 0 (analytic_jet.h). The same
    // differencing as above must find exactly that, which also shows it detects divergence.
    const AnalyticJet jet(nozzle(), sech2(JetGeometry::axisymmetric));
    double worst = 0;
    for (double a : {0.02, 0.1})
        for (double r : {1e-3, 4e-3, 1.5e-2}) {
            const double s = jet.frame().similarityCoordinate(a);
            const double vOverR = jet.profile().at(s, r).vOverY;
            const Mat3 numeric = differenceGradient(jet, at(a, 0.6 * r, 0.8 * r), 1e-6);
            const double divergence = numeric.trace();
            EXPECT_NEAR(divergence, vOverR, 1e-5 * std::abs(vOverR)) << a << " " << r;
            EXPECT_GT(std::abs(vOverR), 1e-3 * numeric.norm()) << "1000× the planar tolerance";
            worst = std::max(worst, std::abs(divergence - vOverR) / std::abs(vOverR));
        }
    measured("axisymmetric sech2 |div U - v/r|/|v/r|", worst);
}

TEST(BickleyJet, CentrelineDecaysAsCubeRootAndHalfWidthGrowsAsTwoThirds) {
    // u_c = C1 s^(−1/3), so u_c s^(1/3) is constant; the half-velocity width, found here by
    // bisection on the sampled field, is y½ = arcsech(1/√2) s^(2/3)/C3 = 0.88137 s^(2/3)/C3.
    const AnalyticJet jet(nozzle(), sech2(JetGeometry::planar));
    double worstDecay = 0, worstWidth = 0;
    for (double a : {0.009, 0.02, 0.1, 0.5, 2.0}) {
        const double s = a - coreLength + jet.virtualOrigin();
        const double centre = axialU(jet, at(a, 0));
        EXPECT_NEAR(centre, jet.centrelineVelocity(a), 1e-13 * centre);
        const double decay = centre * std::cbrt(s) / jet.C1() - 1;
        EXPECT_NEAR(decay, 0.0, 1e-14);
        worstDecay = std::max(worstDecay, std::abs(decay));
        double lo = 0, hi = 1.0;
        for (int k = 0; k < 200 && hi - lo > 1e-15 * hi; ++k) {
            const double mid = 0.5 * (lo + hi);
            (axialU(jet, at(a, mid)) > 0.5 * centre ? lo : hi) = mid;
        }
        const double width =
            0.5 * (lo + hi) * jet.C3() / std::cbrt(s * s) / std::acosh(std::sqrt(2.0)) - 1;
        EXPECT_NEAR(width, 0.0, 1e-12) << "a = " << a;
        worstWidth = std::max(worstWidth, std::abs(width));
    }
    measured("max |u_c s^(1/3)/C1 - 1|", worstDecay);
    measured("max |y_half C3/(0.88137 s^(2/3)) - 1|", worstWidth);
}

TEST(BickleyJet, MomentumFluxIsConservedAndVolumeFluxIsSchlichtings) {
    // ∫u² dy = (4/3) C1²/C3 = K = 2 b U0² at every s, in the frozen core too; the volume flux
    // is Schlichting's Q = ∫u dy = 3.3019 (Kν s)^(1/3). Simpson with 20000 intervals over
    // |η| ≤ 20: quadrature error ~h⁴ ≈ 1e-11, tail sech⁴(20) ≈ 1e-34.
    const AnalyticJet jet(nozzle(), sech2(JetGeometry::planar));
    const double K = 2 * nozzleRadius * U0 * U0;
    double worstMomentum = 0, worstVolume = 0;
    for (double a : {2e-3, 0.01, 0.1, 1.0}) {
        const double s = jet.frame().similarityCoordinate(a);
        const double span = 20 * std::cbrt(s * s) / jet.C3();
        const auto u = [&](double y) { return axialU(jet, at(a, y, 1e-3)); };
        const double momentum = simpson([&](double y) { return u(y) * u(y); }, -span, span, 20000);
        const double volume = simpson(u, -span, span, 20000);
        EXPECT_NEAR(momentum / K, 1.0, 1e-9) << "a = " << a;
        EXPECT_NEAR(volume / (3.3019 * std::cbrt(K * sech2Viscosity * s)), 1.0, 2e-5) << a;
        worstMomentum = std::max(worstMomentum, std::abs(momentum / K - 1));
        worstVolume = std::max(worstVolume,
                               std::abs(volume / (3.3019 * std::cbrt(K * sech2Viscosity * s)) - 1));
    }
    measured("planar max |int u^2 dy / K - 1|", worstMomentum);
    measured("planar max |Q / 3.3019(K nu s)^(1/3) - 1|", worstVolume);
}

TEST(BickleyJet, EntrainsTowardTheAxis) {
    // v = C2 s^(−2/3) g(η), g = 2η sech²η − tanh η: outward for η < 1.0886 (sinh 2η = 4η),
    // inward beyond, → −C2 s^(−2/3) far out (at η ≈ 18 the neglected 2η sech²η < 1e-13).
    for (JetGeometry geometry : {JetGeometry::planar, JetGeometry::axisymmetric}) {
        const AnalyticJet jet(nozzle(), sech2(geometry));
        const Vec3 outward = nozzle().crossSpanDirection;
        const double a = 0.05;
        const double s = jet.frame().similarityCoordinate(a);
        const double yPerEta = std::cbrt(s * s) / jet.C3();
        EXPECT_GT(sampleU(jet, at(a, 1.0 * yPerEta)).dot(outward), 0.0);
        EXPECT_LT(sampleU(jet, at(a, 1.2 * yPerEta)).dot(outward), 0.0);
        const double farField = -jet.C2() / std::cbrt(s * s);
        EXPECT_NEAR(sampleU(jet, at(a, 18 * yPerEta)).dot(outward), farField,
                    1e-12 * std::abs(farField));
        if (geometry == JetGeometry::planar) { // odd in y: inward from the other side too
            EXPECT_NEAR(sampleU(jet, at(a, -18 * yPerEta)).dot(outward), -farField,
                        1e-12 * std::abs(farField));
        }
    }
}

// ---------------------------------------------------------------- gradients of every carrier

enum class Carrier { planarSech2, axisymmetricSech2, roundLaminar };

std::unique_ptr<CarrierField> makeJet(Carrier carrier, const JetNozzle& n = nozzle()) {
    switch (carrier) {
    case Carrier::planarSech2: return std::make_unique<AnalyticJet>(n, sech2(JetGeometry::planar));
    case Carrier::axisymmetricSech2:
        return std::make_unique<AnalyticJet>(n, sech2(JetGeometry::axisymmetric));
    case Carrier::roundLaminar: return std::make_unique<RoundLaminarJet>(n, roundJet());
    }
    return nullptr;
}

void PrintTo(Carrier carrier, std::ostream* os) {
    constexpr const char* names[] = {"planarSech2", "axisymmetricSech2", "roundLaminar"};
    *os << names[static_cast<int>(carrier)];
}

class JetGradient : public ::testing::TestWithParam<Carrier> {};

TEST_P(JetGradient, AnalyticGradientMatchesCentralDifferences) {
    // dU_i/dx_j in closed form against central differences (h = 1e-6 m) in the core (a = 2, 4,
    // 7 mm), beyond it, near and on the axis, and far out. Widths are ≥ 1.7 mm, so truncation
    // is ~(h/w)² ≈ 4e-7 relative; tolerance 2e-6|∇U| + 1e-6 1/s (the far field is ~1e-3 1/s).
    const std::unique_ptr<CarrierField> field = makeJet(GetParam());
    double worst = 0;
    for (double a : {2e-3, 4e-3, 7e-3, 0.009, 0.012, 0.05, 0.3, 1.5})
        for (double y : {0.0, 1e-5, 1e-3, 4e-3, -4e-3, 1.5e-2, 6e-2})
            for (double z : {0.0, 2e-3}) {
                const Vec3 point = at(a, y, z);
                const Mat3 analytic = sampleGradient(*field, point);
                ASSERT_TRUE(analytic.allFinite()) << "a = " << a << " y = " << y;
                const Mat3 numeric = differenceGradient(*field, point, 1e-6);
                const double error = (analytic - numeric).norm();
                EXPECT_LE(error, 2e-6 * analytic.norm() + 1e-6)
                    << "a = " << a << " y = " << y << " z = " << z << "\nanalytic\n"
                    << analytic << "\nnumeric\n"
                    << numeric;
                worst = std::max(worst, error / (analytic.norm() + 1));
            }
    measured("max |grad - FD|/(|grad| + 1 1/s)", worst);
}

TEST_P(JetGradient, ExactlyOnTheAxisTheHoopTermTakesItsLimit) {
    // With the axis along x and the point exactly on it (r = 0, e_r undefined): no NaN, U along
    // the axis, and for the axisymmetric carriers ∂U_y/∂y = ∂U_z/∂z = ∂v/∂r (v/r → ∂v/∂r).
    JetNozzle n;
    n.radius = nozzleRadius;
    const std::unique_ptr<CarrierField> field = makeJet(GetParam(), n);
    for (double a : {0.0, 4e-3, 0.05, 0.5}) {
        const Vec3 point(a, 0, 0);
        const Mat3 gradient = sampleGradient(*field, point);
        ASSERT_TRUE(gradient.allFinite()) << "a = " << a;
        const Vec3 u = sampleU(*field, point);
        EXPECT_EQ(u.y(), 0.0);
        EXPECT_EQ(u.z(), 0.0);
        EXPECT_GT(u.x(), 0.0);
        if (a < 1e-3) continue; // the exit plane itself: central differences straddle the jump
        const Mat3 numeric = differenceGradient(*field, point, 1e-6);
        EXPECT_LE((gradient - numeric).norm(), 2e-6 * gradient.norm() + 1e-6) << gradient;
        if (GetParam() != Carrier::planarSech2) {
            EXPECT_NEAR(gradient(1, 1), gradient(2, 2), 1e-12 * gradient.norm());
            // and the axial/radial limit agrees with a point 1e-300 m off the axis
            const Mat3 nearby = sampleGradient(*field, Vec3(a, 1e-300, 0));
            EXPECT_LE((nearby - gradient).norm(), 1e-12 * gradient.norm() + 1e-12) << nearby;
        }
    }
}

std::string carrierName(const ::testing::TestParamInfo<Carrier>& info) {
    constexpr const char* names[] = {"planarSech2", "axisymmetricSech2", "roundLaminar"};
    return names[static_cast<int>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(Carriers, JetGradient,
                         ::testing::Values(Carrier::planarSech2, Carrier::axisymmetricSech2,
                                           Carrier::roundLaminar),
                         carrierName);

// ---------------------------------------------------------------- Schlichting's round jet

TEST(RoundLaminarJet, SatisfiesContinuityInThreeDimensions) {
    // ∂u/∂s + (1/r)∂(r v)/∂r = 0 is the trace of the Cartesian ∇U: central differences
    // (h = 1e-6 m, widths ≥ 1.7 mm: truncation ~4e-7|∇U|) over the developed jet and the axis.
    const RoundLaminarJet jet(nozzle(), roundJet(0.0));
    double worst = 0, steepest = 0;
    for (double a : {0.002, 0.02, 0.2, 2.0})
        for (double r : {0.0, 2e-4, 1e-3, 3e-3, 1e-2, 4e-2}) {
            const Mat3 numeric = differenceGradient(jet, at(a, 0.8 * r, 0.6 * r), 1e-6);
            EXPECT_LE(std::abs(numeric.trace()), 1e-6 * numeric.norm()) << a << " " << r;
            worst = std::max(worst, std::abs(numeric.trace()) / numeric.norm());
            steepest = std::max(steepest, numeric.norm());
        }
    EXPECT_GT(steepest, 1000.0);
    measured("round max |div U|/|grad U| (FD)", worst);
}

TEST(RoundLaminarJet, MomentumFluxIsConservedAndVolumeFluxIs8PiNuS) {
    // ∫u² 2πr dr = K = πR²U0² and ∫u 2πr dr = 8πν s (Schlichting) at every s. Simpson over
    // ξ ≤ 4000 with 4e5 intervals: tails ~ξ^(−6) (momentum) and 32/ξ² ≈ 2e-6 (volume, added
    // back in closed form: ∫_X^∞ 2πr u dr = 4π A s/(c²(1 + X²/4)) with A/c² = 2ν).
    const RoundLaminarJet jet(nozzle(), roundJet(0.0));
    const double K = std::numbers::pi * nozzleRadius * nozzleRadius * U0 * U0;
    EXPECT_NEAR(jet.momentumFlux() / K, 1.0, 1e-15);
    double worstMomentum = 0, worstVolume = 0;
    for (double a : {1e-9, 0.05, 0.5, 5.0}) {
        const double s = a + jet.virtualOrigin();
        const double xiMax = 4000;
        const double reach = xiMax * s / jet.profile().similarity;
        const auto u = [&](double r) { return axialU(jet, at(a, 0.6 * r, 0.8 * r)); };
        const double momentum = simpson(
            [&](double r) { return u(r) * u(r) * 2 * std::numbers::pi * r; }, 0, reach, 400000);
        const double tail = 8 * std::numbers::pi * roundViscosity * s / (1 + xiMax * xiMax / 4);
        const double volume =
            simpson([&](double r) { return u(r) * 2 * std::numbers::pi * r; }, 0, reach, 400000) +
            tail;
        const double Q = 8 * std::numbers::pi * roundViscosity * s;
        EXPECT_NEAR(momentum / K, 1.0, 1e-8) << "a = " << a;
        EXPECT_NEAR(volume / Q, 1.0, 1e-8) << "a = " << a;
        worstMomentum = std::max(worstMomentum, std::abs(momentum / K - 1));
        worstVolume = std::max(worstVolume, std::abs(volume / Q - 1));
    }
    measured("round max |int u^2 2 pi r dr / K - 1|", worstMomentum);
    measured("round max |Q/(8 pi nu s) - 1|", worstVolume);
}

TEST(RoundLaminarJet, CentrelineDecaysAsOneOverS) {
    // u_c = 3K/(8πν s): u_c·s is constant; s0 = 3K/(8πν U0) = (3/8) R² U0/ν puts U0 at the
    // core end; v ∝ ξ(1 − ξ²/4) points outward for ξ < 2 and inward (entrainment) beyond.
    const RoundLaminarJet jet(nozzle(), roundJet());
    EXPECT_NEAR(jet.virtualOrigin(), 3.0 / 8 * nozzleRadius * nozzleRadius * U0 / roundViscosity,
                1e-15);
    double worst = 0;
    for (double a : {0.009, 0.01, 0.1, 1.0, 10.0}) {
        const double s = a - coreLength + jet.virtualOrigin();
        const double centre = axialU(jet, at(a, 0, 0));
        EXPECT_NEAR(centre, jet.centrelineVelocity(a), 1e-13 * centre);
        worst = std::max(worst, std::abs(centre * s / jet.profile().amplitude - 1));
        const double rPerXi = s / jet.profile().similarity;
        const Vec3 radial = nozzle().crossSpanDirection;
        EXPECT_GT(sampleU(jet, at(a, 1.9 * rPerXi)).dot(radial), 0.0);
        EXPECT_LT(sampleU(jet, at(a, 2.1 * rPerXi)).dot(radial), 0.0);
    }
    EXPECT_LT(worst, 1e-14);
    EXPECT_NEAR(axialU(jet, at(coreLength, 0)), U0, 1e-12 * U0);
    measured("round max |u_c s / (3K/(8 pi nu)) - 1|", worst);
}

// ---------------------------------------------------------------- nozzle frame, core, input

TEST(JetFrame, CoreEndIsContinuousInUAndTheGasBehindTheNozzleIsAtRest) {
    // u(coreLength⁻, y) = u(virtualOrigin, y) = u(coreLength⁺, y); in the core U ∥ axis
    // (v = 0) and u does not vary along it; behind the exit plane U = 0 and ∇U = 0.
    for (Carrier carrier :
         {Carrier::planarSech2, Carrier::axisymmetricSech2, Carrier::roundLaminar}) {
        const std::unique_ptr<CarrierField> jet = makeJet(carrier);
        const double eps = 1e-10; // |∂u/∂a| ≤ 1e4 1/s: jump of u across ±eps below 1e-6 m/s
        EXPECT_NEAR(axialU(*jet, at(coreLength, 0)), U0, 1e-12 * U0);
        EXPECT_NEAR(axialU(*jet, at(1e-4, 0)), U0, 1e-12 * U0);
        for (double y : {0.0, 1e-3, 3e-3, 8e-3}) {
            const double before = axialU(*jet, at(coreLength - eps, y));
            const double after = axialU(*jet, at(coreLength + eps, y));
            EXPECT_NEAR(before, after, 1e-6) << "y = " << y;
            EXPECT_NEAR(axialU(*jet, at(1e-3, y)), before, 1e-12 * U0) << "frozen core";
            const Vec3 core = sampleU(*jet, at(4e-3, y, 1e-3));
            EXPECT_LT((core - core.dot(nozzle().axis) * nozzle().axis).norm(), 1e-13 * U0);
            EXPECT_EQ(sampleU(*jet, at(-1e-6, y)), Vec3::Zero());
            EXPECT_EQ(sampleGradient(*jet, at(-1e-6, y)), Mat3::Zero());
        }
        EXPECT_GT(axialU(*jet, at(coreLength, 1e-3)), 0.1 * U0);
    }
}

TEST(JetFrame, BatchSamplingMatchesPointSamplingAndFillsOnlyWhatIsAsked) {
    const RoundLaminarJet jet(nozzle(), roundJet());
    std::vector<Vec3> points;
    for (int k = 0; k < 50; ++k) points.push_back(at(-0.01 + 0.004 * k, 1e-4 * k, -5e-5 * k));
    CarrierSample out;
    jet.sample(points, 0.0, {.velocityGradient = true}, out);
    ASSERT_EQ(out.velocity.size(), points.size());
    ASSERT_EQ(out.velocityGradient.size(), points.size());
    for (std::size_t k = 0; k < points.size(); ++k) {
        EXPECT_EQ(out.velocity[k], sampleU(jet, points[k]));
        EXPECT_EQ(out.velocityGradient[k], sampleGradient(jet, points[k]));
    }
    jet.sample(std::span(points).first(7), 0.0, {}, out);
    EXPECT_EQ(out.velocity.size(), 7u);
    EXPECT_TRUE(out.velocityGradient.empty());
}

TEST(AnalyticJet, ExplicitCoefficientsAndContinuityOfC2) {
    // Given C1 and C3: C2 = C1/(3C3), s0 = (C1/U0)³, u = C1 s^(−1/3) sech²(C3 y/s^(2/3)).
    AnalyticJetParameters parameters = sech2(JetGeometry::planar);
    parameters.viscosity = 0; // unused with explicit coefficients
    parameters.C1 = 7.0;
    parameters.C3 = 30.0;
    const AnalyticJet jet(nozzle(), parameters);
    EXPECT_DOUBLE_EQ(jet.C2(), 7.0 / 90.0);
    EXPECT_NEAR(jet.virtualOrigin(), std::pow(7.0 / 25.0, 3), 1e-16);
    EXPECT_NEAR(jet.momentumFlux(), 4.0 / 3.0 * 49 / 30, 1e-14);
    const double a = 0.1, y = 2e-3, s = a - coreLength + jet.virtualOrigin();
    const double sech = 1 / std::cosh(30 * y / std::cbrt(s * s));
    EXPECT_NEAR(axialU(jet, at(a, y)), 7 / std::cbrt(s) * sech * sech, 1e-13);
    EXPECT_NEAR(axialU(jet, at(coreLength, 0)), U0, 1e-12 * U0);
    EXPECT_NE(jet.describe().find("planar"), std::string::npos);

    parameters.C2 = 7.0 / 90.0 * (1 + 1e-12); // consistent within 1e-9: accepted
    EXPECT_NO_THROW(AnalyticJet(nozzle(), parameters));
    parameters.C2 = 7.0 / 90.0 * (1 + 1e-8);
    try {
        AnalyticJet rejected(nozzle(), parameters);
        FAIL() << "an inconsistent C2 must be rejected";
    } catch (const std::invalid_argument& error) {
        EXPECT_NE(std::string(error.what()).find("C2"), std::string::npos) << error.what();
        EXPECT_NE(std::string(error.what()).find("C1/(3 C3)"), std::string::npos) << error.what();
    }
    parameters.C2.reset();
    parameters.C3.reset();
    EXPECT_THROW(AnalyticJet(nozzle(), parameters), std::invalid_argument) << "C1 without C3";
}

TEST(JetFrame, RejectsInvalidNozzlesAndParameters) {
    JetNozzle n = nozzle();
    n.axis *= 2;
    EXPECT_THROW(RoundLaminarJet(n, roundJet()), std::invalid_argument) << "non-unit axis";
    n = nozzle();
    n.crossSpanDirection = n.axis;
    EXPECT_THROW(AnalyticJet(n, sech2(JetGeometry::planar)), std::invalid_argument);
    EXPECT_NO_THROW(AnalyticJet(n, sech2(JetGeometry::axisymmetric))) << "e_y unused";
    n = nozzle();
    n.radius = 0;
    EXPECT_THROW(AnalyticJet(n, sech2(JetGeometry::planar)), std::invalid_argument);
    EXPECT_THROW(AnalyticJet(nozzle(), sech2(JetGeometry::planar, -1e-3)), std::invalid_argument);
    RoundLaminarJetParameters still = roundJet();
    still.nozzleVelocity = 0;
    EXPECT_THROW(RoundLaminarJet(nozzle(), still), std::invalid_argument);
    AnalyticJetParameters inviscid = sech2(JetGeometry::axisymmetric);
    inviscid.viscosity = 0;
    EXPECT_THROW(AnalyticJet(nozzle(), inviscid), std::invalid_argument);
}

} // namespace
} // namespace slides
