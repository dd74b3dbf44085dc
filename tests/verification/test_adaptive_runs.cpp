// ctest-labels: adaptive
// Runs with `time.integrator adaptiveRungeKutta` (Section 4.2.3, Eq. 4.18–4.29, Algorithm 2):
// - a particle falling from rest under gravity and Stokes drag in still gas follows the closed
//   form v(t) = v_t (1 − e^(−t/τ)) to the tolerance, with global steps of 4 τ (beyond explicit
//   stability: the step is split into sub-steps), and more closely for a smaller tolerance;
// - in a gas oscillating in time, sampled at each step's middle, the error falls as dt²;
// - a charged particle in E and B fields and a uniform stream follows the exact Lorentz–drag
//   flow (Eq. 2.93; integrate/lorentz_flow.h) to the tolerance;
// - in the sech² jet of Eq. 5.10/5.11 the exponential midpoint rule's paths converge to the
//   adaptive ones as its step halves, and the adaptive paths do not depend on the step;
// - a run resumed from the state of a step (each particle's trial sub-step kept as model state)
//   continues bit for bit, and one thread or two give the same particles bit for bit; a NaN gas
//   stops the run naming the particle (not an endless loop of rejected sub-steps);
// - a whole run reports its sub-steps in summary.json, and bad tolerances or terms it cannot
//   take are refused naming file, line and key (exit status 2).
#include "../support/broken_cases.h"
#include "../support/case_runs.h"
#include "../support/test_scenes.h"
#include "slides/carrier/oscillating_gas.h"
#include "slides/config/scene_reader.h"
#include "slides/physics/body_force.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <omp.h>

#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace slides {
namespace {

struct Fall {
    double velocityError, positionError; ///< relative to the closed form's
    long steps, subSteps;
};

/// One 50 µm particle (τ = 77 ms) falling from rest in still air for 12 τ, 3 global steps.
Fall fallFor(double tolerance) {
    Scene scene = test::singleParticleScene();
    scene.physics.drag = DragModel::stokes;
    scene.physics.gravity = Vec3(0, 0, -9.81);
    scene.time.integrator = Integrator::adaptiveRungeKutta;
    scene.time.tolerance = tolerance;
    const double tau = stokesResponseTime(scene.particles.density, scene.particles.radius.value,
                                          scene.fluid.density, scene.fluid.kinematicViscosity);
    scene.time.dt = 4 * tau;
    scene.time.endTime = 12 * tau;
    const test::UniformFlow stillGas(Vec3::Zero());
    Stepper stepper(scene, stillGas);
    while (!stepper.finished()) stepper.step();
    // v(t) = v_t (1 − e^(−t/τ)), x(t) = v_t (t − τ (1 − e^(−t/τ))), v_t = τ g_eff.
    const Vec3 terminal = tau * bodyAcceleration(scene.physics.gravity, scene.particles.density,
                                                 scene.fluid.density, scene.physics.buoyancy);
    const double t = stepper.time();
    const Vec3 exactV = terminal * -std::expm1(-t / tau);
    const Vec3 exactX = terminal * (t + tau * std::expm1(-t / tau));
    const Vec3 x = stepper.cloud().position.at(0), v = stepper.cloud().velocity.at(0);
    return {(v - exactV).norm() / exactV.norm(), (x - exactX).norm() / exactX.norm(),
            stepper.steps(), stepper.snapshot().adaptiveSteps->attempted};
}

TEST(AdaptiveRuns, FallsUnderGravityAndStokesDragAsTheClosedForm) {
    double previous = INFINITY;
    for (const double tolerance : {1e-4, 1e-6, 1e-8}) {
        const Fall fall = fallFor(tolerance);
        std::printf("TOL %g: velocity error %.2e, position error %.2e, %ld sub-steps in %ld "
                    "steps\n",
                    tolerance, fall.velocityError, fall.positionError, fall.subSteps, fall.steps);
        EXPECT_EQ(fall.steps, 3);
        // dt = 4 τ is past the explicit stability limit (≈ 3.3 τ): at least 2 sub-steps a step.
        EXPECT_GE(fall.subSteps, 2 * fall.steps);
        // Each sub-step's error is held below TOL × the speed (and TOL × the radius for the
        // position, ≪ the 0.9 m fallen); the relaxation damps earlier errors: the whole fall's
        // stays below TOL.
        EXPECT_LT(fall.velocityError, tolerance);
        EXPECT_LT(fall.positionError, tolerance);
        EXPECT_LT(fall.velocityError, previous);
        previous = fall.velocityError;
    }
}

TEST(AdaptiveRuns, ATolerancePastDoublePrecisionEndsAtItsRounding) {
    // TOL = 1e-300 asks for errors no double can hold: the error scale stops at 4 ε of the
    // state (integrate/adaptive_runge_kutta.h), so the fall takes about as many sub-steps as at
    // the finest tolerance it can meet, and ends as close to the closed form as doubles allow.
    const Fall finest = fallFor(1e-300), fine = fallFor(1e-12);
    std::printf("TOL 1e-300: velocity error %.2e, position error %.2e, %ld sub-steps; TOL 1e-12: "
                "%ld sub-steps\n",
                finest.velocityError, finest.positionError, finest.subSteps, fine.subSteps);
    EXPECT_LT(finest.subSteps, 10 * fine.subSteps);
    EXPECT_LT(finest.velocityError, 1e-13);
    EXPECT_LT(finest.positionError, 1e-13);
}

TEST(AdaptiveRuns, ChargedParticleFollowsTheExactLorentzDragFlow) {
    // A 50 µm particle (τ = 77 ms, m = 1.3e-9 kg) of charge 1.3e-7 C in E = (1 0 0) V/m,
    // B = (0 0 0.5) T (|Ω| = qB/m = 50 rad/s, qE/m = 100 m/s²) and a uniform stream under Stokes
    // drag: integrate/lorentz_flow.h is the exact solution there, which the exponential
    // midpoint rule takes. Over 10 τ (6 turns), in 10 steps of τ, the adaptive sub-steps agree
    // with it to TOL = 1e-8 of the particle's path length.
    Scene scene = test::singleParticleScene();
    scene.physics.drag = DragModel::stokes;
    ElectromagneticSettings& fields = scene.physics.electromagnetic;
    fields.model = ElectromagneticModel::lorentz;
    fields.electricField = Vec3(1, 0, 0);
    fields.magneticField = Vec3(0, 0, 0.5);
    fields.chargeValue = 1.3e-7;
    const double tau = stokesResponseTime(scene.particles.density, scene.particles.radius.value,
                                          scene.fluid.density, scene.fluid.kinematicViscosity);
    scene.time.dt = tau;
    scene.time.endTime = 10 * tau;
    scene.time.tolerance = 1e-8;
    const test::UniformFlow stream(Vec3(0.5, 0.2, 0));
    const auto runWith = [&](Integrator integrator) {
        scene.time.integrator = integrator;
        auto stepper = std::make_unique<Stepper>(scene, stream);
        while (!stepper->finished()) stepper->step();
        return stepper;
    };
    const auto exact = runWith(Integrator::exponentialMidpoint);
    const auto adaptive = runWith(Integrator::adaptiveRungeKutta);
    const Vec3 x = adaptive->cloud().position.at(0), v = adaptive->cloud().velocity.at(0);
    const Vec3 exactX = exact->cloud().position.at(0), exactV = exact->cloud().velocity.at(0);
    std::printf("charged: |x| %.3g m, error %.2e m; |v| %.3g m/s, error %.2e m/s; %ld sub-steps\n",
                exactX.norm(), (x - exactX).norm(), exactV.norm(), (v - exactV).norm(),
                adaptive->snapshot().adaptiveSteps->attempted);
    EXPECT_LT((x - exactX).norm(), 1e-8 * exactX.norm());
    EXPECT_LT((v - exactV).norm(), 1e-8 * exactV.norm());
}

TEST(AdaptiveRuns, ANonFiniteGasStopsTheRunNamingTheParticle) {
    // A NaN error estimate is neither within the tolerance nor a reason to shrink the sub-step
    // without end: the step is kept, and the stepper's check stops the run at the NaN state.
    Scene scene = test::singleParticleScene();
    scene.time.integrator = Integrator::adaptiveRungeKutta;
    const test::UniformFlow brokenGas(Vec3(std::nan(""), 0, 0));
    Stepper stepper(scene, brokenGas);
    try {
        stepper.step();
        FAIL() << "the NaN gas went unnoticed";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("particle 0 reached a non-finite state"),
                  std::string::npos)
            << error.what();
    }
}

TEST(AdaptiveRuns, InAnOscillatingGasConvergesAtSecondOrderInTheStep) {
    // u(t) = U sin ωt (carrier/oscillating_gas.h), a 10 µm particle from rest under Stokes drag
    // (τ = 3.1 ms, ωτ ≈ 1 at 50 Hz): v(t) = A (sin ωt − ωτ cos ωt + ωτ e^(−t/τ)),
    // A = U / (1 + ω²τ²). The gas is sampled at each step's middle time, so with the sub-steps
    // resolving the rest (TOL = 1e-10) the error falls as dt² (at the step's start: as dt).
    // Tolerance ±0.2 on the order, as for the fixed-step integrators.
    Scene scene = test::singleParticleScene();
    scene.physics.drag = DragModel::stokes;
    scene.particles.radius.value = 10e-6;
    scene.injection.crossSpanSpeed = 0;
    scene.time.integrator = Integrator::adaptiveRungeKutta;
    scene.time.tolerance = 1e-10;
    scene.time.endTime = 0.02;
    const double amplitude = 1, frequency = 50;
    const OscillatingGas gas(Vec3(amplitude, 0, 0), frequency, 293.15);
    const double tau = stokesResponseTime(scene.particles.density, scene.particles.radius.value,
                                          scene.fluid.density, scene.fluid.kinematicViscosity);
    const double omega = 2 * std::numbers::pi * frequency, t = scene.time.endTime;
    const double A = amplitude / (1 + omega * omega * tau * tau);
    const double exact = A * (std::sin(omega * t) - omega * tau * std::cos(omega * t) +
                              omega * tau * std::exp(-t / tau));
    std::vector<double> errors;
    for (const double dt : {1e-3, 0.5e-3, 0.25e-3}) {
        scene.time.dt = dt;
        Stepper stepper(scene, gas);
        while (!stepper.finished()) stepper.step();
        errors.push_back(std::abs(stepper.cloud().velocity.at(0).x() - exact));
    }
    for (std::size_t k = 1; k < errors.size(); ++k) {
        const double order = std::log2(errors[k - 1] / errors[k]);
        std::printf("oscillating gas: error %.3e m/s, observed order %.3f\n", errors[k], order);
        EXPECT_NEAR(order, 2.0, 0.2);
    }
}

struct JetRun {
    std::map<ParticleId, Vec3> positions;
    long subSteps = 0;
};

/// The default spray with 10 µm particles (τ_St = 4.6 ms, about the flight time: they follow
/// the jet's curvature and shear only in part), 200 of them, 3 ms, no target.
JetRun runJet(Integrator integrator, double dt) {
    Scene scene = readScene(test::defaultCase);
    scene.particles.count = 200;
    scene.particles.radius.value = 10e-6;
    scene.injection.mode = InjectionMode::allAtStart;
    scene.collisions.model = CollisionModel::none;
    scene.surfaces.clear();
    scene.time.integrator = integrator;
    scene.time.tolerance = 1e-11;
    scene.time.dt = dt;
    scene.time.endTime = 3e-3;
    scene.time.stopWhenAllDone = false;
    const auto carrier = test::carrierOf(scene);
    Stepper stepper(scene, *carrier);
    while (!stepper.finished()) stepper.step();
    JetRun run;
    const ParticleCloud& cloud = stepper.cloud();
    for (std::size_t i = 0; i < cloud.size(); ++i) run.positions[cloud.id[i]] = cloud.position[i];
    if (const auto steps = stepper.snapshot().adaptiveSteps) run.subSteps = steps->attempted;
    return run;
}

/// The largest distance between the positions of the particles both runs hold.
double largestDistance(const JetRun& a, const JetRun& b) {
    double largest = 0;
    for (const auto& [id, x] : a.positions)
        if (b.positions.contains(id)) largest = std::max(largest, (x - b.positions.at(id)).norm());
    return largest;
}

TEST(AdaptiveRuns, AgreesWithTheExponentialMidpointRuleInTheAnalyticJet) {
    // The midpoint rule converges (at order p ≥ 1) to the exact paths as dt halves: the error
    // left at dt/2 is |x(dt) − x(dt/2)| / (2^p − 1), at most the last correction. The adaptive
    // run (TOL = 1e-11: the velocity error it allows, TOL × 25 m/s a sub-step, moves a particle
    // by ~1e-10 m over the 3 ms) at the case's dt of 10 µs lies within that correction of the
    // fixed-step runs, ever closer to them as their dt halves — and at dt = 1 µs it ends where
    // it did at 10 µs: its error follows the tolerance, not the step.
    const JetRun adaptive = runJet(Integrator::adaptiveRungeKutta, 1e-5);
    const JetRun adaptiveAtSmallStep = runJet(Integrator::adaptiveRungeKutta, 1e-6);
    std::vector<JetRun> midpoint;
    for (const double dt : {1e-6, 0.5e-6, 0.25e-6})
        midpoint.push_back(runJet(Integrator::exponentialMidpoint, dt));
    ASSERT_GT(adaptive.positions.size(), 100u); // a few leave the domain box
    for (std::size_t k = 1; k < midpoint.size(); ++k) {
        const double correction = largestDistance(midpoint[k - 1], midpoint[k]);
        const double distance = largestDistance(adaptive, midpoint[k]);
        std::printf("midpoint at dt/%d: correction %.2e m, adaptive to it %.2e m\n", 1 << k,
                    correction, distance);
        EXPECT_LT(distance, correction);
        EXPECT_LT(distance, largestDistance(adaptive, midpoint[k - 1]));
    }
    const double stepDependence = largestDistance(adaptive, adaptiveAtSmallStep);
    std::printf("adaptive at dt 10 µs and 1 µs: %.2e m apart (%ld sub-steps at 10 µs)\n",
                stepDependence, adaptive.subSteps);
    EXPECT_LT(stepDependence, 0.01 * largestDistance(midpoint[0], midpoint[1]));
}

/// The default spray with 10 µm particles at dt = 0.1 ms (several sub-steps a step), no
/// collisions; its target plate stays.
Scene sprayOfSubSteppingParticles() {
    Scene scene = readScene(test::defaultCase);
    scene.particles.count = 200;
    scene.particles.radius.value = 10e-6;
    scene.collisions.model = CollisionModel::none;
    scene.time.integrator = Integrator::adaptiveRungeKutta;
    scene.time.tolerance = 1e-8;
    scene.time.dt = 1e-4;
    scene.time.endTime = 6e-3;
    return scene;
}

TEST(AdaptiveRuns, RestartFromTheStateOfAStepContinuesBitForBit) {
    // Each particle's next trial sub-step is model state of the cloud (checkpointed with it):
    // a stepper resumed from another's state after 10 steps ends as the uninterrupted one.
    // Resumed with the trial steps cleared (every particle starting from dt again) it does not:
    // they carry the step control from one global step to the next.
    const Scene scene = sprayOfSubSteppingParticles();
    const auto carrier = test::carrierOf(scene);
    Stepper whole(scene, *carrier);
    while (!whole.finished()) whole.step();
    ASSERT_FALSE(whole.arrivals().empty());

    Stepper first(scene, *carrier);
    for (int n = 0; n < 10; ++n) first.step();
    const auto resumed = [&](bool keepTrialSteps) {
        ParticleCloud cloud = first.cloud();
        if (!keepTrialSteps) std::fill(cloud.modelState.begin(), cloud.modelState.end(), 0.0);
        auto second = std::make_unique<Stepper>(scene, *carrier);
        second->resume(first.counters(), cloud, first.arrivals());
        while (!second->finished()) second->step();
        return second;
    };
    const auto restarted = resumed(true);
    ASSERT_EQ(restarted->cloud().size(), whole.cloud().size());
    ASSERT_EQ(restarted->arrivals().size(), whole.arrivals().size());
    for (std::size_t i = 0; i < whole.arrivals().size(); ++i) {
        EXPECT_EQ(restarted->arrivals()[i].id, whole.arrivals()[i].id);
        EXPECT_EQ(restarted->arrivals()[i].position, whole.arrivals()[i].position) << i;
        EXPECT_EQ(restarted->arrivals()[i].time, whole.arrivals()[i].time) << i;
    }
    const auto cleared = resumed(false);
    bool differs = cleared->arrivals().size() != whole.arrivals().size();
    for (std::size_t i = 0; !differs && i < whole.arrivals().size(); ++i)
        differs = cleared->arrivals()[i].position != whole.arrivals()[i].position;
    EXPECT_TRUE(differs) << "the trial steps changed nothing: are they kept?";
}

TEST(AdaptiveRuns, AnyThreadCountGivesBitIdenticalParticles) {
    // 2500 particles: three blocks of the cloud (1024 each) on the threads. A particle's
    // sub-steps do not depend on its block, so one thread and two agree bit for bit.
    Scene scene = sprayOfSubSteppingParticles();
    scene.particles.count = 2500;
    scene.injection.mode = InjectionMode::allAtStart;
    scene.time.endTime = 2e-3;
    const auto carrier = test::carrierOf(scene);
    const auto runWith = [&](int threads) {
        omp_set_num_threads(threads);
        auto stepper = std::make_unique<Stepper>(scene, *carrier);
        while (!stepper->finished()) stepper->step();
        return stepper;
    };
    const auto one = runWith(1), two = runWith(2);
    ASSERT_EQ(one->cloud().size(), 2500u);
    ASSERT_EQ(two->cloud().id, one->cloud().id);
    EXPECT_EQ(two->cloud().position, one->cloud().position);
    EXPECT_EQ(two->cloud().velocity, one->cloud().velocity);
    EXPECT_EQ(two->cloud().modelState, one->cloud().modelState);
    EXPECT_EQ(two->snapshot().adaptiveSteps->attempted, one->snapshot().adaptiveSteps->attempted);
}

TEST(AdaptiveRuns, ReportItsSubStepsInTheSummary) {
    test::ScratchDirectory scratch("adaptive-summary");
    test::writeBrokenCase(scratch, "    integrator      exponentialMidpoint;",
                          "    integrator      adaptiveRungeKutta;\n    tolerance       1e-5;");
    std::string text = test::slurp(scratch.path / "constant" / "slidesProperties");
    text.replace(text.find("count       8000;"), 17, "count       300; ");
    text.replace(text.find("endTime         0.1;"), 20, "endTime         5e-3;");
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
    ASSERT_EQ(test::runCli(scratch.path.string() + " --quiet", scratch.path / "log"), 0)
        << test::slurp(scratch.path / "log");
    const auto summary =
        nlohmann::json::parse(test::slurp(scratch.path / "slides" / "summary.json"));
    EXPECT_EQ(summary["settings"]["time"]["integrator"], "adaptiveRungeKutta");
    EXPECT_EQ(summary["settings"]["time"]["tolerance"], 1e-5);
    const auto& steps = summary["performance"]["adaptiveSteps"];
    const long particleSteps = summary["performance"]["particleSteps"];
    // Every particle step takes one sub-step at least; rejected ones are among those tried.
    EXPECT_GE(steps["attempted"].get<long>(), particleSteps);
    EXPECT_LE(steps["rejected"].get<long>(), steps["attempted"].get<long>());
    EXPECT_GE(steps["rejected"].get<long>(), 0);
}

constexpr const char* integratorLine = "    integrator      exponentialMidpoint;";

const test::BrokenCase brokenAdaptiveCases[] = {
    {"zeroTolerance", integratorLine,
     "    integrator      adaptiveRungeKutta;\n    tolerance       0;", 1,
     "key 'time.tolerance': must be a positive number"},
    {"toleranceOfOne", integratorLine,
     "    integrator      adaptiveRungeKutta;\n    tolerance       1;", 1,
     "key 'time.tolerance': must be below 1"},
    {"infiniteTolerance", integratorLine,
     "    integrator      adaptiveRungeKutta;\n    tolerance       1e999;", 1,
     "key 'time.tolerance': number '1e999' is out of range"},
    {"toleranceWithoutAdaptiveSteps", integratorLine,
     "    integrator      exponentialMidpoint;\n    tolerance       1e-6;", 1,
     "key 'time.tolerance': controls the steps of adaptiveRungeKutta only, and time.integrator "
     "is exponentialMidpoint"},
    {"adaptiveWithAddedMass", integratorLine,
     "    integrator      adaptiveRungeKutta;\n}\nphysics { addedMass on; }\ntime {", 0,
     "key 'time.integrator': adaptiveRungeKutta does not take the unsteady forces"},
};

using test::RefusedCase;
INSTANTIATE_TEST_SUITE_P(AdaptiveRuns, RefusedCase, ::testing::ValuesIn(brokenAdaptiveCases),
                         test::brokenCaseName);

} // namespace
} // namespace slides
