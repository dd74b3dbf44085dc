// ctest-labels: transient carrier
// The pulsed analytic jets (carrier/pulsed_jet.h): the nozzle signal s(t) = 1 + A sin ωt carried
// downstream at the mean jet's centreline speed, U(x, t) = s(t − τ(a)) U_mean(x), τ(a) =
// ∫_0^a da'/u_c, on the sech² jet of Eq. 5.10/5.11 (planar and axisymmetric) and Schlichting's
// round laminar jet:
// - ∂U/∂t and ∇U in closed form against central differences of U in t and x;
// - amplitude 0 is the steady jet bit for bit (and the dictionary builds no pulsed jet then);
// - the phase t − τ(a) is constant along the centreline characteristic da/dt = u_c(a) (RK4);
// - U, ∇U and ∂U/∂t averaged over a period are the steady jet's U, ∇U and 0;
// - a tracer (Stokes time 1.2e-5 s) follows the pulsed gas, v = U − τ_p DU/Dt + O(τ_p²);
// - the pulsation keys reach the Scene and build the carrier; A ≥ 1 and a missing frequency are
//   refused with the key named (exit status 2 from the command line);
// - the example case foamCases/pulsedJet runs from its dictionary through the scene analysis and
//   accounts for every particle.
#include "../support/case_runs.h"
#include "../support/dictionary_scenes.h"
#include "../support/test_scenes.h"
#include "slides/carrier/analytic_jet.h"
#include "slides/carrier/pulsed_jet.h"
#include "slides/carrier/round_laminar_jet.h"
#include "slides/config/dictionary.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <numbers>
#include <regex>

namespace slides {
namespace {

using test::sceneWithCarrier;

using std::numbers::pi;

constexpr double U0 = 25;           // nozzle exit velocity [m/s]
constexpr double coreLength = 8e-3; // [m]
constexpr double amplitude = 0.3;   // A
constexpr double frequency = 400; // f [Hz]: ∂s/∂a = ωA/u_c ≥ 30 1/m, a visible part of ∇U
constexpr double omega = 2 * pi * frequency;

JetNozzle obliqueNozzle() {
    JetNozzle n;
    n.centre = Vec3(0.01, -0.02, 0.005);
    n.axis = Vec3(1, 2, 2) / 3.0; // oblique, so no Cartesian component is special
    n.radius = 2e-3;
    n.crossSpanDirection = Vec3(2, -2, 1) / 3.0; // ⟂ axis
    return n;
}

enum class Profile { planarSech2, axisymmetricSech2, roundLaminar };

constexpr const char* profileNames[] = {"planarSech2", "axisymmetricSech2", "roundLaminar"};

/// The steady jet of profile: the sech² jet with ν_eff = 1.4e-3 m²/s, the round laminar jet
/// with ν = 2e-4 m²/s (Re = 250).
template <typename Build>
auto withJet(Profile profile, const JetNozzle& nozzle, Build build, double core = coreLength) {
    if (profile == Profile::roundLaminar)
        return build(
            std::make_unique<RoundLaminarJet>(nozzle, RoundLaminarJetParameters{U0, 2e-4, core}));
    AnalyticJetParameters sech2;
    sech2.profile =
        profile == Profile::planarSech2 ? JetGeometry::planar : JetGeometry::axisymmetric;
    sech2.nozzleVelocity = U0;
    sech2.viscosity = 1.4e-3;
    sech2.coreLength = core;
    return build(std::make_unique<AnalyticJet>(nozzle, sech2));
}

std::unique_ptr<CarrierField> steadyJet(Profile profile, const JetNozzle& nozzle) {
    return withJet(profile, nozzle,
                   [](auto jet) { return std::unique_ptr<CarrierField>(std::move(jet)); });
}

std::unique_ptr<CarrierField> pulsedJet(Profile profile, const JetNozzle& nozzle,
                                        double a = amplitude, double core = coreLength) {
    return withJet(
        profile, nozzle,
        [a]<typename Jet>(std::unique_ptr<Jet> jet) {
            return std::unique_ptr<CarrierField>(
                std::make_unique<PulsedJet<Jet>>(std::move(jet), JetPulsation{a, frequency}));
        },
        core);
}

/// Axial distance a, cross-span y, and z along e_a × e_y from the nozzle of obliqueNozzle().
Vec3 at(double a, double y, double z = 0) {
    const JetNozzle n = obliqueNozzle();
    return n.centre + a * n.axis + y * n.crossSpanDirection +
           z * n.axis.cross(n.crossSpanDirection);
}

constexpr CarrierNeeds everything{.velocityGradient = true, .timeDerivative = true};

CarrierSample sampleAt(const CarrierField& field, const Vec3& point, double t,
                       CarrierNeeds needs = everything) {
    CarrierSample out;
    field.sample(std::span(&point, 1), t, needs, out);
    return out;
}

Vec3 velocityAt(const CarrierField& field, const Vec3& point, double t) {
    return sampleAt(field, point, t, {}).velocity[0];
}

const double axialStations[] = {2e-3, 4e-3, 7e-3, 0.009, 0.012, 0.05, 0.3, 1.5};
const double crossStations[] = {0.0, 1e-5, 1e-3, 4e-3, -4e-3, 1.5e-2, 6e-2};
const double times[] = {0.0, 1.3e-3, 3.7e-3, 0.05};

class PulsedJetProfiles : public ::testing::TestWithParam<Profile> {};

TEST_P(PulsedJetProfiles, TimeDerivativeAndGradientMatchCentralDifferences) {
    // ∂U/∂t = ωA cos ω(t − τ) U_mean against (U(t + h) − U(t − h))/2h, h = 1e-7 s: truncation
    // (ωh)²/6 = 1.1e-8 of ωA|U_mean|, round-off ε|U|/h = 2e-9|U| against ωA|U_mean| ≥ 750|U|/(1
    // + A), so tolerance 1e-7 ωA|U_mean| (+1e-9 m/s² where U vanishes). ∇U = s ∇U_mean + U_mean ⊗
    // ∇s against central differences in x (h = 1e-6 m; widths ≥ 1.7 mm and wavelengths u_c/f ≥ 7
    // mm, u_c ≥ 2.8 m/s out to a = 1.5 m: truncation ≤ 4e-7), with the steady jets' tolerance
    // 2e-6|∇U| + 1e-6 1/s. The pulsation's part U_mean ⊗ ∇s is reported.
    const auto field = pulsedJet(GetParam(), obliqueNozzle());
    const auto steady = steadyJet(GetParam(), obliqueNozzle());
    double worstRate = 0, worstGradient = 0, largestPulsePart = 0;
    for (const double t : times)
        for (const double a : axialStations)
            for (const double y : crossStations)
                for (const double z : {0.0, 2e-3}) {
                    const Vec3 point = at(a, y, z);
                    const CarrierSample gas = sampleAt(*field, point, t);
                    const double scale =
                        omega * amplitude * gas.velocity[0].norm() / (1 - amplitude);
                    const double h = 1e-7;
                    const Vec3 rate =
                        (velocityAt(*field, point, t + h) - velocityAt(*field, point, t - h)) /
                        (2 * h);
                    const double rateError = (gas.velocityTimeDerivative[0] - rate).norm();
                    EXPECT_LE(rateError, 1e-7 * scale + 1e-9)
                        << "t = " << t << " a = " << a << " y = " << y;
                    worstRate = std::max(worstRate, rateError / (scale + 1e-300));

                    const Mat3& analytic = gas.velocityGradient[0];
                    Mat3 numeric;
                    for (int j = 0; j < 3; ++j) {
                        const Vec3 step = 1e-6 * Vec3::Unit(j);
                        numeric.col(j) = (velocityAt(*field, point + step, t) -
                                          velocityAt(*field, point - step, t)) /
                                         2e-6;
                    }
                    const double error = (analytic - numeric).norm();
                    EXPECT_LE(error, 2e-6 * analytic.norm() + 1e-6)
                        << "t = " << t << " a = " << a << " y = " << y << " z = " << z
                        << "\nanalytic\n"
                        << analytic << "\nnumeric\n"
                        << numeric;
                    worstGradient = std::max(worstGradient, error / (analytic.norm() + 1));
                    // The pulse's own part, ∇U − s ∇U_mean = U_mean ⊗ ∇s, against the whole.
                    const CarrierSample mean =
                        sampleAt(*steady, point, t, {.velocityGradient = true});
                    const double signal = gas.velocity[0].norm() / mean.velocity[0].norm();
                    largestPulsePart = std::max(
                        largestPulsePart,
                        (analytic - signal * mean.velocityGradient[0]).norm() / analytic.norm());
                }
    std::printf("%s: max |∂U/∂t − FD|/(ωA|U|) = %.2e, max |∇U − FD|/(|∇U| + 1 1/s) = %.2e, "
                "largest |U_mean ⊗ ∇s|/|∇U| = %.3f\n",
                profileNames[static_cast<int>(GetParam())], worstRate, worstGradient,
                largestPulsePart);
    EXPECT_GT(largestPulsePart, 0.05) << "the pulse's gradient part is tested, not negligible";
}

TEST_P(PulsedJetProfiles, ZeroAmplitudeIsTheSteadyJetBitForBit) {
    // s = 1 + 0·sin φ = 1 and ∇s = 0 exactly: U and ∇U equal the steady jet's to the last bit.
    const auto steady = steadyJet(GetParam(), obliqueNozzle());
    const auto still = pulsedJet(GetParam(), obliqueNozzle(), 0.0);
    for (const double t : times)
        for (const double a : {-1e-3, 0.0, 4e-3, 0.05, 1.5})
            for (const double y : {0.0, 1e-3, -6e-2}) {
                const Vec3 point = at(a, y, 1e-3);
                const CarrierSample expected =
                    sampleAt(*steady, point, t, {.velocityGradient = true});
                const CarrierSample pulsed = sampleAt(*still, point, t);
                EXPECT_EQ(pulsed.velocity[0], expected.velocity[0]) << a << " " << y;
                EXPECT_EQ(pulsed.velocityGradient[0], expected.velocityGradient[0]);
                EXPECT_EQ(pulsed.velocityTimeDerivative[0], Vec3::Zero());
            }
}

TEST_P(PulsedJetProfiles, PhaseIsConstantAlongTheCentrelineCharacteristic) {
    // da/dt = u_c(a) from the exit plane at t0, RK4 with h = 1e-6 s (the core, 0.32 ms at U0,
    // a whole number of steps; then u_c smooth, RK4's error (h/T)⁴ with T = s/u_c ≥ 0.1 ms):
    // the signal s(t − τ(a(t))) stays at s(t0) within 1e-10 out to a = 0.3 m.
    withJet(GetParam(), obliqueNozzle(), [&]<typename Jet>(std::unique_ptr<Jet> jet) {
        const PulsedJet<Jet> pulsed(std::move(jet), JetPulsation{amplitude, frequency});
        const auto speed = [&](double a) { return pulsed.centrelineVelocity(a); };
        for (const double t0 : {0.0, 0.3e-3, 1.1e-3}) {
            const double start = pulsed.signal(0.0, t0).value;
            double a = 0, t = t0, worst = 0;
            const double h = 1e-6;
            long steps = 0;
            while (a < 0.3) {
                const double k1 = speed(a), k2 = speed(a + 0.5 * h * k1),
                             k3 = speed(a + 0.5 * h * k2), k4 = speed(a + h * k3);
                a += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
                t = t0 + static_cast<double>(++steps) * h;
                worst = std::max(worst, std::abs(pulsed.signal(a, t).value - start));
            }
            std::printf("%s, t0 = %g s: %ld steps to a = %.3f m in %.4f s, max |s − s(t0)| = "
                        "%.2e\n",
                        profileNames[static_cast<int>(GetParam())], t0, steps, a, t - t0, worst);
            EXPECT_LT(worst, 1e-10) << "t0 = " << t0;
            // and the signal did change at fixed a meanwhile: the test follows a moving phase
            EXPECT_GT(std::abs(pulsed.signal(a, t0 + 0.25 / frequency).value -
                               pulsed.signal(a, t0).value),
                      0.1);
        }
        return 0;
    });
}

TEST_P(PulsedJetProfiles, PeriodAverageIsTheSteadyJet) {
    // U, ∇U and ∂U/∂t are linear in sin φ and cos φ: the rectangle rule over a period with 16
    // equal steps integrates them exactly, so their mean is U_mean, ∇U_mean and 0 to round-off
    // (a sum of 16 terms, 16 × 1e-15 of the largest term, plus the rounding of the phase
    // ω(t − τ), ε|φ| of it: φ reaches 800 rad at a = 1.5 m in the round jet).
    const auto steady = steadyJet(GetParam(), obliqueNozzle());
    const auto field = pulsedJet(GetParam(), obliqueNozzle());
    constexpr int samples = 16;
    double worst = 0;
    for (const double a : axialStations)
        for (const double y : {0.0, 1e-3, -4e-3, 1.5e-2}) {
            const Vec3 point = at(a, y, 2e-3);
            Vec3 meanU = Vec3::Zero(), meanRate = Vec3::Zero();
            Mat3 meanGradient = Mat3::Zero();
            double largestU = 0, largestGradient = 0, largestRate = 0;
            for (int k = 0; k < samples; ++k) {
                const CarrierSample gas = sampleAt(*field, point, 1e-3 + k / (samples * frequency));
                meanU += gas.velocity[0] / samples;
                meanGradient += gas.velocityGradient[0] / samples;
                meanRate += gas.velocityTimeDerivative[0] / samples;
                largestU = std::max(largestU, gas.velocity[0].norm());
                largestGradient = std::max(largestGradient, gas.velocityGradient[0].norm());
                largestRate = std::max(largestRate, gas.velocityTimeDerivative[0].norm());
            }
            const CarrierSample expected =
                sampleAt(*steady, point, 0.0, {.velocityGradient = true});
            const double travel =
                withJet(GetParam(), obliqueNozzle(), [a](auto jet) { return jet->travelTime(a); });
            const double roundOff =
                samples * 1e-15 + std::numeric_limits<double>::epsilon() * omega * (travel + 1);
            EXPECT_LE((meanU - expected.velocity[0]).norm(), roundOff * largestU) << a << " " << y;
            EXPECT_LE((meanGradient - expected.velocityGradient[0]).norm(),
                      roundOff * largestGradient)
                << a << " " << y;
            EXPECT_LE(meanRate.norm(), roundOff * largestRate) << a << " " << y;
            worst = std::max(worst, (meanU - expected.velocity[0]).norm() / largestU);
        }
    std::printf("%s: max |<U> − U_mean|/max |U| = %.2e\n",
                profileNames[static_cast<int>(GetParam())], worst);
}

std::string profileName(const ::testing::TestParamInfo<Profile>& info) {
    return profileNames[static_cast<int>(info.param)];
}

INSTANTIATE_TEST_SUITE_P(Profiles, PulsedJetProfiles,
                         ::testing::Values(Profile::planarSech2, Profile::axisymmetricSech2,
                                           Profile::roundLaminar),
                         profileName);

/// The largest |v − (U − τ_p DU/Dt)| and |v − U| of a particle of radius R (ρp = 1000 in air,
/// Stokes drag alone, τ_p = 2R²ρp/(9ρfν)) released at rest 1 mm off the axis of the pulsed
/// axisymmetric sech² jet without a core (whose end is a jump in v), after 50 τ_p, each over
/// τ_p |DU/Dt| (DU/Dt = ∂U/∂t + (∇U) U).
struct TracerSlip {
    double firstOrderResidual = 0; ///< max |v − U + τ_p DU/Dt| / (τ_p |DU/Dt|)_max
    double slip = 0;               ///< max |v − U| / (τ_p |DU/Dt|)_max
};

TracerSlip tracerSlip(double radius) {
    Scene scene = test::singleParticleScene();
    scene.nozzle.centre = Vec3(0, 1e-3, 0);
    scene.particles.density = 1000;
    scene.particles.radius.value = radius;
    scene.physics.drag = DragModel::stokes;
    const double tauP = 2 * radius * radius * 1000 / (9 * 1.2 * 1.5e-5);
    scene.time.dt = tauP / 20;
    scene.time.endTime = 4e-3;
    JetNozzle nozzle;
    nozzle.radius = 2e-3;
    const auto field = pulsedJet(Profile::axisymmetricSech2, nozzle, amplitude, 0.0);
    Stepper stepper(scene, *field);
    double residual = 0, slip = 0, scale = 0;
    while (!stepper.finished()) {
        stepper.step();
        if (stepper.time() < 50 * tauP) continue;
        const Vec3& x = stepper.cloud().position[0];
        const Vec3& v = stepper.cloud().velocity[0];
        const CarrierSample gas = sampleAt(*field, x, stepper.time());
        const Vec3 acceleration =
            gas.velocityTimeDerivative[0] + gas.velocityGradient[0] * gas.velocity[0];
        residual = std::max(residual, (v - gas.velocity[0] + tauP * acceleration).norm());
        slip = std::max(slip, (v - gas.velocity[0]).norm());
        scale = std::max(scale, tauP * acceleration.norm());
    }
    return {residual / scale, slip / scale};
}

TEST(PulsedJet, TracerFollowsThePulsedGas) {
    // Stokes drag alone: dv/dt = (U − v)/τ_p gives v = U − τ_p DU/Dt + O(τ_p²) (Maxey & Riley
    // 1983, the tracer limit). At R = 1 µm (τ_p = 1.2e-5 s, ωτ_p = 0.03) the slip is τ_p|DU/Dt|
    // to first order and the rest is O(ωτ_p) of it; halving R quarters τ_p and the rest.
    const TracerSlip coarse = tracerSlip(1e-6), fine = tracerSlip(0.5e-6);
    std::printf("R = 1 µm: max slip %.3f, residual %.2e of τ_p|DU/Dt|; R = 0.5 µm: %.3f, %.2e\n",
                coarse.slip, coarse.firstOrderResidual, fine.slip, fine.firstOrderResidual);
    EXPECT_LT(coarse.slip, 1.1);
    EXPECT_GT(coarse.slip, 0.5);
    EXPECT_LT(coarse.firstOrderResidual, 0.1);
    EXPECT_LT(fine.firstOrderResidual, 0.5 * coarse.firstOrderResidual);
}

/// The InputError message of reading carrier, or "" if it was accepted.
std::string refusal(const std::string& carrier) {
    try {
        sceneWithCarrier(carrier);
    } catch (const InputError& error) {
        return error.what();
    }
    return "";
}

TEST(PulsedJetKeys, ReachTheSceneAndBuildThePulsedCarrier) {
    for (const std::string type : {"analyticJet", "roundLaminarJet"}) {
        const std::string coeffs =
            "type " + type + "; " + type + "Coeffs { nozzleVelocity 25; effectiveViscosity 1e-3; ";
        const Scene pulsed =
            sceneWithCarrier(coeffs + "pulsation { amplitude 0.3; frequency 100; } }");
        ASSERT_TRUE(pulsed.carrier.pulsation.has_value()) << type;
        EXPECT_EQ(pulsed.carrier.pulsation->amplitude, 0.3);
        EXPECT_EQ(pulsed.carrier.pulsation->frequency, 100);
        const auto gas = carrierOf(pulsed);
        EXPECT_FALSE(gas->steady()) << type;
        EXPECT_TRUE(gas->provides().timeDerivative);
        EXPECT_NE(gas->describe().find("pulsed nozzle"), std::string::npos) << gas->describe();
        // At t = 0 the nozzle's signal is 1: the exit-plane velocity is U0, growing at ωA U0.
        const CarrierSample exit = sampleAt(*gas, Vec3::Zero(), 0.0);
        EXPECT_NEAR(exit.velocity[0].x(), 25, 1e-12);
        EXPECT_NEAR(exit.velocityTimeDerivative[0].x(), 2 * pi * 100 * 0.3 * 25, 1e-9);

        // Amplitude 0 (or no pulsation) is the steady jet, no wrapper.
        for (const std::string still : {"pulsation { amplitude 0; frequency 100; } }", "}"}) {
            const Scene steady = sceneWithCarrier(coeffs + still);
            EXPECT_FALSE(steady.carrier.pulsation.has_value());
            EXPECT_TRUE(carrierOf(steady)->steady());
        }
        // A ≥ 1 would stop or reverse the nozzle; a pulsation needs its frequency.
        const std::string key = "carrier." + type + "Coeffs.pulsation.";
        const std::string atOne = refusal(coeffs + "pulsation { amplitude 1; frequency 100; } }");
        EXPECT_NE(atOne.find(key + "amplitude"), std::string::npos) << atOne;
        EXPECT_NE(atOne.find("below 1"), std::string::npos) << atOne;
        const std::string noFrequency = refusal(coeffs + "pulsation { amplitude 0.2; } }");
        EXPECT_NE(noFrequency.find(key + "frequency"), std::string::npos) << noFrequency;
        const std::string negative =
            refusal(coeffs + "pulsation { amplitude 0.2; frequency -5; } }");
        EXPECT_NE(negative.find(key + "frequency"), std::string::npos) << negative;
    }
}

const std::filesystem::path exampleCase = test::sourceDir / "foamCases" / "pulsedJet";

TEST(PulsedJetCase, RunsThroughTheSceneAnalysisAndAccountsForEveryParticle) {
    // The shipped example from its dictionary, every optional term left to the scene analysis:
    // exit status 0, the summary's carrier the pulsed jet, and every injected particle arrived,
    // escaped or still active.
    const test::ScratchDirectory scratch("pulsed-jet-case");
    const auto output = scratch.path / "out";
    ASSERT_EQ(test::runCli(exampleCase.string() + " --quiet --output " + output.string(),
                           scratch.path / "log"),
              0)
        << test::slurp(scratch.path / "log");
    const auto summary = nlohmann::json::parse(test::slurp(output / "summary.json"));
    const auto& particles = summary["particles"];
    const long injected = particles["injected"];
    long arrived = 0;
    for (const auto& count : particles["arrived"]) arrived += count.get<long>();
    const long escaped = particles["escaped"], active = particles["active"];
    std::printf("pulsed jet case: %ld injected, %ld arrived, %ld escaped, %ld active\n", injected,
                arrived, escaped, active);
    EXPECT_EQ(injected, particles["requested"].get<long>());
    EXPECT_EQ(arrived + escaped + active, injected);
    EXPECT_GT(arrived, injected / 2);
    EXPECT_NE(summary.dump().find("pulsed nozzle"), std::string::npos);
    EXPECT_TRUE(summary.contains("sceneAnalysis"));

    // The same case with A = 1: refused, exit status 2, the file and the key named.
    std::string text = test::slurp(exampleCase / "constant" / "slidesProperties");
    text = std::regex_replace(text, std::regex("amplitude +[0-9.]+;"), "amplitude 1;");
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet", scratch.path / "refused.log"), 2);
    const std::string message = test::slurp(scratch.path / "refused.log");
    EXPECT_NE(message.find("slidesProperties"), std::string::npos) << message;
    EXPECT_NE(message.find("carrier.analyticJetCoeffs.pulsation.amplitude"), std::string::npos)
        << message;
}

} // namespace
} // namespace slides
