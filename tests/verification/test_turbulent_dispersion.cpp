// ctest-labels: turbulence physics
// Turbulent dispersion (Section 3.9, Eq. 3.31; physics/dispersion.h) in homogeneous isotropic
// turbulence at rest (k = 1 m²/s², ε = 1 m²/s³, C_μ = 0.09, Sc_t = 0.7: σ² = 2/3 m²/s²,
// T_L = 3 C_μ k/(2 Sc_t ε) = 0.193 s). Checked against:
//  - the model's own distributions: u' ~ N(0, 2k/3) per component, uncorrelated, carrying the
//    whole k; eddy lifetimes Exp(T_L) (Kolmogorov–Smirnov); crossing after l_e;
//  - Taylor (1921): fluid tracers, whose u' has the autocorrelation e^(−t/T_L), spread as
//    ⟨x²⟩ = 2σ²T_L² (t/T_L − 1 + e^(−t/T_L)) — σ²t² at short times, 2σ²T_L t at long times —
//    for every step from 0.1 to 2 T_L, with the long-time diffusivity σ²T_L = C_μ k²/(ε Sc_t)
//    = ν_t/Sc_t;
//  - Tchen's theory (Hinze, Turbulence, 1975, §5.3): a Stokes particle of response time τ
//    filters u'; for the Langevin u' its ⟨x²⟩ follows from the moment equations of the linear
//    system (u', v, x), so heavier particles (Stokes number St = τ/T_L) spread less at every
//    time. The eddy-interaction model adds crossing of eddies, so it spreads less still;
//  - determinism: 1 and 2 threads give bit-identical particles.
// Statistical tolerances: every Monte-Carlo mean is compared with 4 standard errors estimated
// from the same sample (a two-sided 6e-5 chance of a false failure per comparison; the seeds
// are fixed, so the outcome is reproducible). Per particle the sample is r²/3 = (x² + y² + z²)/3,
// independent between particles (the three components of one particle share eddy lifetimes).
#include "../support/gas_scenes.h"
#include "../support/test_scenes.h"
#include "slides/physics/dispersion.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace slides {
namespace {

constexpr double kineticEnergy = 1.0; // k [m²/s²]
constexpr double dissipation = 1.0;   // ε [m²/s³]
const DispersionConstants constants;  // C_μ = 0.09, Sc_t = 0.7
const double variance = 2.0 / 3.0 * kineticEnergy;
const double lagrangianTime = lagrangianTimeScale(constants, kineticEnergy, dissipation);

struct Estimate {
    double mean = 0;
    double standardError = 0;
};

Estimate estimate(const std::vector<double>& values) {
    const double n = static_cast<double>(values.size());
    double sum = 0;
    for (double value : values) sum += value;
    const double mean = sum / n;
    double squares = 0;
    for (double value : values) squares += (value - mean) * (value - mean);
    return {mean, std::sqrt(squares / (n - 1) / n)};
}

/// Taylor (1921) for the autocorrelation e^(−t/T_L): ⟨x²⟩ = 2σ²T_L² (a − 1 + e^(−a)).
double taylorDispersion(double t) {
    const double a = t / lagrangianTime;
    return 2.0 * variance * lagrangianTime * lagrangianTime * (a + std::expm1(-a));
}

/// Tchen: ⟨x²⟩(t) of a particle starting at rest, dv/dt = (u' − v)/τ, u' the stationary
/// Ornstein–Uhlenbeck process (σ², T_L). The covariance P of (u', v, x) obeys
/// dP/dt = A P + P Aᵀ + Q, integrated by RK4 with 4000 steps (error far below 1e-6).
double tchenDispersion(double tau, double t) {
    Mat3 A;
    A << -1 / lagrangianTime, 0, 0, 1 / tau, -1 / tau, 0, 0, 1, 0;
    Mat3 Q = Mat3::Zero();
    Q(0, 0) = 2 * variance / lagrangianTime;
    Mat3 P = Mat3::Zero();
    P(0, 0) = variance;
    const auto rate = [&](const Mat3& p) -> Mat3 { return A * p + p * A.transpose() + Q; };
    const int steps = 4000;
    const double h = t / steps;
    for (int i = 0; i < steps; ++i) {
        const Mat3 k1 = rate(P);
        const Mat3 k2 = rate(P + 0.5 * h * k1);
        const Mat3 k3 = rate(P + 0.5 * h * k2);
        const Mat3 k4 = rate(P + h * k3);
        P += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    return P(2, 2);
}

/// count particles at rest at the origin in the turbulence, Stokes drag, no gravity.
Scene dispersionScene(DispersionModel model, long count, double particleRadius,
                      double particleDensity, double dt) {
    Scene scene = test::singleParticleScene();
    scene.particles.count = count;
    scene.particles.radius.value = particleRadius;
    scene.particles.density = particleDensity;
    scene.physics.drag = DragModel::stokes;
    scene.physics.dispersion = model;
    scene.time.dt = dt;
    return scene;
}

/// A fluid tracer: R = 1 µm at the gas density, τ = 1.2e-8 s = 6e-8 T_L.
Scene tracerScene(DispersionModel model, long count, double dt) {
    return dispersionScene(model, count, 1e-6, 1.2, dt);
}

/// The particle density giving St = τ_St/T_L for R = 50 µm.
double densityForStokesNumber(double stokes) {
    const Scene scene = test::singleParticleScene();
    return stokes * lagrangianTime /
           stokesResponseTime(1.0, 50e-6, scene.fluid.density, scene.fluid.kinematicViscosity);
}

/// r²/3 of every particle at each of times (ascending, multiples of the scene's dt).
std::vector<std::vector<double>> spreads(Scene scene, const std::vector<double>& times) {
    scene.time.endTime = times.back();
    const test::UniformTurbulentGas gas(kineticEnergy, dissipation, 300.0);
    Stepper stepper(scene, gas);
    std::vector<std::vector<double>> result;
    for (double time : times) {
        while (stepper.time() < time * (1 - 1e-9)) stepper.step();
        std::vector<double>& spread = result.emplace_back();
        for (const Vec3& x : stepper.cloud().position) spread.push_back(x.squaredNorm() / 3);
    }
    return result;
}

TEST(EddySampling, FluctuationsCarryTheWholeEnergyWithoutCorrelation) {
    // Variance 2k/3 per component (Eq. 3.31), so ⟨|u'|²⟩ = 2k; a random direction times a
    // scalar of variance 2k/3 would carry only a third of it and fail by 30 standard errors.
    const int n = 20000;
    const double sigma = fluctuationRms(kineticEnergy);
    std::vector<Vec3> samples;
    for (int i = 0; i < n; ++i) {
        EddyState state;
        drawEddy(state, lagrangianTime, 1.0, {7, static_cast<std::uint64_t>(i)});
        samples.push_back(sigma * state.standardised);
    }
    Vec3 mean = Vec3::Zero();
    Mat3 covariance = Mat3::Zero();
    std::vector<double> energy;
    for (const Vec3& u : samples) {
        mean += u / n;
        covariance += u * u.transpose() / n;
        energy.push_back(u.squaredNorm());
    }
    // Standard errors for Gaussian samples: mean σ/√n, variance σ²√(2/n), correlation 1/√n.
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(mean[c] / sigma, 0.0, 4 / std::sqrt(n));
        EXPECT_NEAR(covariance(c, c) / variance, 1.0, 4 * std::sqrt(2.0 / n));
        for (int d = 0; d < c; ++d)
            EXPECT_NEAR(covariance(c, d) / variance, 0.0, 4 / std::sqrt(n)) << c << d;
    }
    const Estimate kinetic = estimate(energy);
    EXPECT_NEAR(kinetic.mean, 2 * kineticEnergy, 4 * kinetic.standardError);
}

TEST(EddySampling, LifetimesAreExponentialWithMeanTL) {
    const int n = 20000;
    std::vector<double> lifetimes;
    for (int i = 0; i < n; ++i) {
        EddyState state;
        drawEddy(state, lagrangianTime, 1.0, {3, static_cast<std::uint64_t>(i)});
        lifetimes.push_back(state.timeLeft);
    }
    std::sort(lifetimes.begin(), lifetimes.end());
    double distance = 0; // Kolmogorov–Smirnov statistic against 1 − e^(−t/T_L)
    for (int i = 0; i < n; ++i) {
        const double model = -std::expm1(-lifetimes[i] / lagrangianTime);
        distance = std::max(
            {distance, std::abs(model - double(i) / n), std::abs(model - double(i + 1) / n)});
    }
    EXPECT_LT(distance, 1.95 / std::sqrt(n)); // KS critical value at significance 0.001
    const Estimate mean = estimate(lifetimes);
    EXPECT_NEAR(mean.mean, lagrangianTime, 4 * mean.standardError);
}

TEST(EddySampling, TracersNeverCrossEddiesHeavyParticlesCrossAfterTheEddyLength) {
    const double h = 0.5 * lagrangianTime;
    const int steps = 8000; // D = 4000 T_L
    // A tracer moves with its eddy: eddies end by lifetime only, a Poisson process of rate
    // 1/T_L, so D/T_L = 4000 ± √4000 eddies.
    EddyState tracer;
    for (int i = 0; i < steps; ++i)
        eddyInteractionStep(tracer, constants, kineticEnergy, dissipation,
                            {Vec3::Zero(), 1e-9, Vec3::Zero()}, h, {5, 1});
    EXPECT_NEAR(tracer.count, 4000.0, 4 * std::sqrt(4000.0));

    // A particle too heavy to follow (τ = 1e6 s) slipping at s = 1000σ through the eddies
    // crosses each after l_e/s ≈ T_L/958 (corrections O(σ²/s²) = 1e-6), unless its lifetime
    // ends first: the mean interaction time is T_L (1 − e^(−c/T_L)), c = l_e/s.
    const double slip = 1000 * fluctuationRms(kineticEnergy);
    const double crossing = eddyLengthScale(constants, kineticEnergy, dissipation) / slip;
    const double duration = 4 * lagrangianTime;
    EddyState heavy;
    for (int i = 0; i < 8; ++i)
        eddyInteractionStep(heavy, constants, kineticEnergy, dissipation,
                            {Vec3(slip, 0, 0), 1e6, Vec3::Zero()}, duration / 8, {5, 2});
    const double expected = duration / (-lagrangianTime * std::expm1(-crossing / lagrangianTime));
    // Lifetime endings (a fraction c/T_L ≈ 1e-3 of ~3800 eddies) add a spread of a few eddies.
    EXPECT_NEAR(heavy.count, expected, 4 * std::sqrt(expected * crossing / lagrangianTime) + 1)
        << "expected " << expected << " eddies";
}

TEST(EddySampling, AnEddyIsLeftWhereThePathRelativeToItsGasReachesTheLengthLeft) {
    // Without drift the path relative to the eddy gas is Δ(t) = w τ (1 − e^(−t/τ)), so a
    // length L is crossed at t_c = −τ ln(1 − L/(|w|τ)) = τ ln 2 for |w|τ = 2L. The step's
    // ū' is then σ/h (ξ1 t_c + ξ2 (h − t_c)), ξ2 the next eddy of the same stream, which lasts
    // the rest of the step (T_L = 0.193 s, l_e = 0.16 m). Tolerance 1e-14 σ: t_c to ~1e-16
    // relative (a bisection to 2^-40 of the step errs by ~1e-12).
    const double tau = 1e-3, h = 1e-3, length = 1e-3;
    const double sigma = fluctuationRms(kineticEnergy);
    const Vec3 xi1(0.3, -0.2, 0.5), relative(2 * length / tau, 0, 0);
    EddyState state;
    state.standardised = xi1;
    state.timeLeft = 1.0;
    state.lengthLeft = length;
    EddyState next = state;
    drawEddy(next, lagrangianTime, eddyLengthScale(constants, kineticEnergy, dissipation), {7, 3});
    const double crossing = tau * std::log(2.0);
    ASSERT_GT(next.timeLeft, h - crossing) << "the next eddy lasts the step";
    const Vec3 fluctuation =
        eddyInteractionStep(state, constants, kineticEnergy, dissipation,
                            {relative + sigma * xi1, tau, Vec3::Zero()}, h, {7, 3});
    const Vec3 expected = sigma / h * (xi1 * crossing + next.standardised * (h - crossing));
    EXPECT_LE((fluctuation - expected).norm(), 1e-14 * sigma);
    EXPECT_EQ(state.count, 1u);
    EXPECT_EQ(state.standardised, next.standardised);
}

TEST(EddySampling, LaminarGasGivesNoFluctuationAndBrokenInputIsNotHidden) {
    EddyState state;
    const ParticleResponse still{Vec3::Zero(), 1e-3, Vec3::Zero()};
    EXPECT_EQ(eddyInteractionStep(state, constants, 0.0, 0.0, still, 0.1, {1, 1}), Vec3::Zero());
    EXPECT_EQ(langevinStep(state, constants, 0.0, 0.0, 0.1, {1, 1}), Vec3::Zero());
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_FALSE(eddyInteractionStep(state, constants, nan, 1.0, still, 0.1, {1, 1}).allFinite());
    EXPECT_FALSE(langevinStep(state, constants, 1.0, nan, 0.1, {1, 1}).allFinite());
}

struct TracerCase {
    DispersionModel model;
    double stepInLagrangianTimes;
};

class TracerDispersion : public ::testing::TestWithParam<TracerCase> {};

TEST_P(TracerDispersion, FollowsTaylorForAnyStepWithTheKEpsilonDiffusivity) {
    const double dt = GetParam().stepInLagrangianTimes * lagrangianTime;
    const std::vector<double> times = {dt, 2 * lagrangianTime, 6 * lagrangianTime,
                                       10 * lagrangianTime};
    const auto spread = spreads(tracerScene(GetParam().model, 20000, dt), times);
    for (std::size_t j = 0; j < times.size(); ++j) {
        const Estimate measured = estimate(spread[j]);
        EXPECT_NEAR(measured.mean / taylorDispersion(times[j]), 1.0,
                    4 * measured.standardError / taylorDispersion(times[j]))
            << "t = " << times[j] / lagrangianTime << " T_L";
    }
    // Short times: ⟨x²⟩ → σ²t² (ballistic); Taylor's formula is σ²t²(1 − t/(3T_L) + …).
    if (GetParam().stepInLagrangianTimes <= 0.1) {
        const Estimate first = estimate(spread[0]);
        EXPECT_NEAR(first.mean / (variance * dt * dt), 1.0,
                    0.1 / 3 + 4 * first.standardError / (variance * dt * dt));
    }
    // Long times: the diffusivity D = Δ⟨x²⟩/(2Δt) between 6 and 10 T_L against
    // σ² T_L = C_μ k²/(ε Sc_t) (Taylor's slope there is σ²T_L (1 − 6e-4)).
    std::vector<double> diffusivity;
    for (std::size_t i = 0; i < spread[2].size(); ++i)
        diffusivity.push_back((spread[3][i] - spread[2][i]) / (2 * 4 * lagrangianTime));
    const Estimate measured = estimate(diffusivity);
    const double eddyDiffusivity = constants.Cmu * kineticEnergy * kineticEnergy /
                                   (dissipation * constants.turbulentSchmidtNumber);
    EXPECT_NEAR(measured.mean / eddyDiffusivity, 1.0,
                6e-4 + 4 * measured.standardError / eddyDiffusivity);
    RecordProperty("diffusivityOverNutSct", std::to_string(measured.mean / eddyDiffusivity));
}

INSTANTIATE_TEST_SUITE_P(StepsFromATenthToTwoLifetimes, TracerDispersion,
                         ::testing::Values(TracerCase{DispersionModel::eddyInteraction, 0.1},
                                           TracerCase{DispersionModel::eddyInteraction, 0.5},
                                           TracerCase{DispersionModel::eddyInteraction, 1.0},
                                           TracerCase{DispersionModel::eddyInteraction, 2.0},
                                           TracerCase{DispersionModel::langevin, 0.1},
                                           TracerCase{DispersionModel::langevin, 0.5},
                                           TracerCase{DispersionModel::langevin, 1.0},
                                           TracerCase{DispersionModel::langevin, 2.0}),
                         [](const auto& info) {
                             return std::string(info.param.model == DispersionModel::langevin
                                                    ? "langevin"
                                                    : "eddyInteraction") +
                                    "_dt" +
                                    std::to_string(
                                        static_cast<int>(info.param.stepInLagrangianTimes * 10)) +
                                    "tenthsTL";
                         });

TEST(HeavyParticles, LangevinFollowsTchenAndSpreadsLessAsStokesGrows) {
    const double dt = 0.05 * lagrangianTime;
    const double t = 3 * lagrangianTime;
    double previous = taylorDispersion(t); // St = 0
    for (double stokes : {0.5, 2.0}) {
        const double tau = stokes * lagrangianTime;
        const auto spread = spreads(dispersionScene(DispersionModel::langevin, 8000, 50e-6,
                                                    densityForStokesNumber(stokes), dt),
                                    {t});
        const Estimate measured = estimate(spread[0]);
        const double theory = tchenDispersion(tau, t);
        // The step sees ū' constant over dt = 0.05 T_L: a filtering error O((dt/T_L)²) ≈ 0.3 %.
        EXPECT_NEAR(measured.mean / theory, 1.0, 3e-3 + 4 * measured.standardError / theory)
            << "St = " << stokes;
        EXPECT_LT(theory, previous);
        EXPECT_LT(measured.mean + 4 * measured.standardError, previous) << "St = " << stokes;
        previous = theory;
    }
}

TEST(HeavyParticles, LangevinFollowsTchenUnderTheMaxeyRileyStep) {
    // Added mass on: the Maxey–Riley step replaces the drag schemes and must see the same
    // eddies. In uniform turbulence DU/Dt of the mean flow is 0, so added mass only slows the
    // response: τ = τ_St (ρp + ρf/2)/ρp (Eq. 3.4).
    const double dt = 0.05 * lagrangianTime;
    const double t = 3 * lagrangianTime;
    const double stokes = 0.5;
    const double density = densityForStokesNumber(stokes);
    Scene scene = dispersionScene(DispersionModel::langevin, 8000, 50e-6, density, dt);
    scene.physics.addedMass = true;
    const double tau = stokes * lagrangianTime * (density + 0.5 * scene.fluid.density) / density;
    const Estimate measured = estimate(spreads(scene, {t})[0]);
    const double theory = tchenDispersion(tau, t);
    // As under the drag schemes: ū' constant over dt = 0.05 T_L filters O((dt/T_L)²) ≈ 0.3 %.
    EXPECT_NEAR(measured.mean / theory, 1.0, 3e-3 + 4 * measured.standardError / theory);
}

TEST(HeavyParticles, EddyInteractionSpreadsLessAsStokesGrowsBelowTchen) {
    // Crossing eddies shortens the velocity correlation a heavy particle sees, so at every St
    // it spreads at most as much as Tchen's particle, and less as St grows.
    const double dt = 0.05 * lagrangianTime;
    const double t = 3 * lagrangianTime;
    Estimate previous{taylorDispersion(t), 0.0};
    for (double stokes : {0.5, 2.0}) {
        const auto spread = spreads(dispersionScene(DispersionModel::eddyInteraction, 8000, 50e-6,
                                                    densityForStokesNumber(stokes), dt),
                                    {t});
        const Estimate measured = estimate(spread[0]);
        EXPECT_LT(measured.mean - 4 * measured.standardError,
                  tchenDispersion(stokes * lagrangianTime, t))
            << "St = " << stokes;
        EXPECT_LT(measured.mean + 4 * std::hypot(measured.standardError, previous.standardError),
                  previous.mean)
            << "St = " << stokes;
        previous = measured;
    }
}

/// Ids, positions, velocities and temperatures after a run on the given thread count.
std::vector<double> runOnThreads(int threads, DispersionModel model) {
    Scene scene = dispersionScene(model, 3000, 30e-6, 2500, 2 * lagrangianTime);
    scene.physics.drag = DragModel::haiderLevenspiel;
    scene.physics.gravity = Vec3(0, 0, -9.81);
    scene.physics.heatTransfer = HeatTransferModel::ranzMarshall;
    scene.fluid.thermalConductivity = 0.0257;
    scene.fluid.specificHeat = 1005;
    scene.particles.specificHeat = 700;
    scene.particles.injectionTemperature = 500;
    scene.injection.mode = InjectionMode::rate;
    scene.injection.rate = 3000 / lagrangianTime; // entering during the first step
    scene.time.endTime = 20 * lagrangianTime;
    const test::UniformTurbulentGas gas(kineticEnergy, dissipation, 300.0, Vec3(1, 0, 0));
    const int before = omp_get_max_threads();
    omp_set_num_threads(threads);
    Stepper stepper(scene, gas);
    while (!stepper.finished()) stepper.step();
    omp_set_num_threads(before);
    const ParticleCloud& cloud = stepper.cloud();
    std::vector<double> state;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        state.push_back(static_cast<double>(cloud.id[i]));
        for (int c = 0; c < 3; ++c) state.push_back(cloud.position[i][c]);
        for (int c = 0; c < 3; ++c) state.push_back(cloud.velocity[i][c]);
        state.push_back(cloud.temperature.at(i));
    }
    return state;
}

TEST(Determinism, OneAndTwoThreadsGiveBitIdenticalParticles) {
    for (auto model : {DispersionModel::eddyInteraction, DispersionModel::langevin}) {
        const auto one = runOnThreads(1, model);
        const auto two = runOnThreads(2, model);
        ASSERT_EQ(one.size(), two.size());
        EXPECT_TRUE(one == two) << "results differ between 1 and 2 threads";
        EXPECT_GT(one.size(), 1000u);
    }
}

} // namespace
} // namespace slides
