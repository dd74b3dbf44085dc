// ctest-labels: foundation physics
// Particle motion under drag and gravity (Eq. 3.16 with the drag of Eq. 3.17), integrated by
// each integrator of integrate/integrator.h through the real stepper: settling velocity,
// relaxation in a uniform stream against the exact Stokes solution, the observed order of
// accuracy under step halving, and stability for dt = 1000 response times.
#include "../support/test_scenes.h"
#include "slides/physics/body_force.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace slides {
namespace {

using test::singleParticleScene;

/// Runs the stepper to the scene's end time; returns the single particle's (x, v).
std::pair<Vec3, Vec3> runSingleParticle(const Scene& scene, const CarrierField& carrier) {
    Stepper stepper(scene, carrier);
    while (!stepper.finished()) stepper.step();
    EXPECT_EQ(stepper.cloud().size(), 1u);
    return {stepper.cloud().position.at(0), stepper.cloud().velocity.at(0)};
}

class EveryIntegrator : public ::testing::TestWithParam<IntegratorName> {};

TEST_P(EveryIntegrator, SettlesAtTheRootOfTheForceBalance) {
    // In still gas the terminal speed w solves w = |g_eff| τ(w), τ = τ_St / f(Re(w))
    // (Eq. 3.16 with Eq. 3.17). Root by bisection, independent of the integrators.
    Scene scene = singleParticleScene();
    scene.physics.gravity = Vec3(0, 0, -9.81);
    scene.time.integrator = GetParam().value;
    const DragParameters drag{scene.physics.drag, scene.fluid.density,
                              scene.fluid.kinematicViscosity, scene.particles.density};
    const double radius = scene.particles.radius.value;
    const double weight =
        bodyAcceleration(scene.physics.gravity, scene.particles.density, scene.fluid.density, true)
            .norm();
    double low = 0, high = 10;
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (low + high);
        (weight * dragResponseTime(drag, radius, mid) > mid ? low : high) = mid;
    }
    const double terminal = 0.5 * (low + high);
    const double tau = dragResponseTime(drag, radius, terminal);
    scene.time.dt = 0.1 * tau; // stable for explicit Euler as well
    scene.time.endTime = 60 * tau;
    const auto [x, v] = runSingleParticle(scene, test::UniformFlow(Vec3::Zero()));
    EXPECT_NEAR(v.z() / -terminal, 1.0, 1e-9) << "terminal speed " << terminal << " m/s";
    EXPECT_NEAR(v.x(), 0.0, 1e-15);
    EXPECT_NEAR(v.y(), 0.0, 1e-15);
}

TEST_P(EveryIntegrator, RelaxesFromRestLikeTheStokesSolution) {
    // Stokes drag, still gas, released from rest under the effective gravity g (Eq. 3.16):
    // v(t) = τ g (1 − e^(−t/τ)), x(t) = τ g (t − τ (1 − e^(−t/τ))) — by Galilean invariance
    // the relaxation in a uniform stream. Exponential schemes reproduce it to round-off;
    // explicit Euler converges to it at first order (checked in ObservedOrder).
    Scene scene = singleParticleScene();
    scene.physics.drag = DragModel::stokes;
    scene.physics.gravity = Vec3(3.0, -9.81, 0.5);
    scene.time.integrator = GetParam().value;
    const double tau = stokesResponseTime(scene.particles.density, scene.particles.radius.value,
                                          scene.fluid.density, scene.fluid.kinematicViscosity);
    scene.time.dt = 0.05 * tau;
    scene.time.endTime = 2 * tau;
    const auto [x, v] = runSingleParticle(scene, test::UniformFlow(Vec3::Zero()));
    const Vec3 terminal = tau * bodyAcceleration(scene.physics.gravity, scene.particles.density,
                                                 scene.fluid.density, true);
    const double t = scene.time.endTime;
    const Vec3 exactV = terminal * (1 - std::exp(-t / tau));
    const Vec3 exactX = terminal * (t - tau * (1 - std::exp(-t / tau)));
    // Euler: O(dt/τ). Adaptive: each sub-step's error held below TOL × the speed, and the
    // relaxation damps the earlier ones, so the whole run's stays below TOL (measured 3e-11 at
    // TOL = 1e-6: the 5th-order steps of dt = τ/20 resolve e^(−t/τ) far better).
    double tolerance = 1e-12;
    if (GetParam().value == Integrator::explicitEuler) tolerance = 2e-2;
    if (GetParam().value == Integrator::adaptiveRungeKutta) tolerance = scene.time.tolerance;
    EXPECT_LT((v - exactV).norm() / terminal.norm(), tolerance);
    EXPECT_LT((x - exactX).norm() / exactX.norm(), tolerance);
}

/// The integrators whose step is the global dt: their error falls as dt^order.
/// (adaptiveRungeKutta's follows time.tolerance instead: test_adaptive_runge_kutta.cpp.)
std::vector<IntegratorName> fixedStepIntegrators() {
    std::vector<IntegratorName> fixed;
    for (const IntegratorName& integrator : integratorNames())
        if (integrator.value != Integrator::adaptiveRungeKutta) fixed.push_back(integrator);
    return fixed;
}

class FixedStepIntegrator : public ::testing::TestWithParam<IntegratorName> {};

TEST_P(FixedStepIntegrator, ObservedOrderMatchesDesignOrder) {
    // Haider–Levenspiel drag (τ depends on the slip) in a curved, non-uniform flow: the
    // error against a reference run at dt/256 must fall as dt^p under halving, p the design
    // order. Tolerance ±0.2 on p covers the pre-asymptotic drift between dt and dt/8.
    Scene scene = singleParticleScene();
    scene.time.integrator = GetParam().value;
    scene.injection.crossSpanSpeed = 0;
    scene.nozzle.centre = Vec3(0.02, 0.01, 0);
    const test::SwirlingStagnationFlow flow(5.0, 8.0, Vec3(0.5, 0, 0)); // rotates, bounded
    const double tau = stokesResponseTime(scene.particles.density, scene.particles.radius.value,
                                          scene.fluid.density, scene.fluid.kinematicViscosity);
    const double coarse = 0.2 * tau;
    scene.time.endTime = 8 * tau;

    Scene reference = scene;
    reference.time.integrator = Integrator::exponentialMidpoint;
    reference.time.dt = coarse / 256;
    const Vec3 exact = runSingleParticle(reference, flow).first;

    std::vector<double> errors;
    for (double dt = coarse; dt >= coarse / 8; dt /= 2) {
        scene.time.dt = dt;
        errors.push_back((runSingleParticle(scene, flow).first - exact).norm());
    }
    for (std::size_t k = 1; k < errors.size(); ++k) {
        const double order = std::log2(errors[k - 1] / errors[k]);
        std::printf("%s: dt = τ/%g, error %.3e m, observed order %.3f\n",
                    std::string(GetParam().name).c_str(), 5.0 * (1 << k), errors[k], order);
        EXPECT_NEAR(order, GetParam().order, 0.2)
            << "halving " << k << ": errors " << errors[k - 1] << " -> " << errors[k];
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, EveryIntegrator, ::testing::ValuesIn(integratorNames()),
                         [](const auto& info) { return std::string(info.param.name); });
INSTANTIATE_TEST_SUITE_P(Integrators, FixedStepIntegrator,
                         ::testing::ValuesIn(fixedStepIntegrators()),
                         [](const auto& info) { return std::string(info.param.name); });

class ExponentialIntegrator : public ::testing::TestWithParam<Integrator> {};

TEST_P(ExponentialIntegrator, StableAtThousandResponseTimes) {
    // dt = 1000 τ: the exact relaxation leaves v = U + τ g_eff after one step (e^(−1000) = 0),
    // with no overshoot, no growth and no NaN, for any number of steps.
    Scene scene = singleParticleScene();
    scene.physics.drag = DragModel::stokes;
    scene.physics.gravity = Vec3(0, -9.81, 0);
    scene.time.integrator = GetParam();
    const double tau = stokesResponseTime(scene.particles.density, scene.particles.radius.value,
                                          scene.fluid.density, scene.fluid.kinematicViscosity);
    scene.time.dt = 1000 * tau;
    scene.time.endTime = 500 * scene.time.dt;
    const Vec3 stream(20.0, 0, 0);
    const auto [x, v] = runSingleParticle(scene, test::UniformFlow(stream));
    const Vec3 terminal =
        stream + tau * bodyAcceleration(scene.physics.gravity, scene.particles.density,
                                        scene.fluid.density, true);
    EXPECT_TRUE(x.allFinite());
    EXPECT_LT((v - terminal).norm(), 1e-12 * terminal.norm());
}

TEST_P(ExponentialIntegrator, TracksNonUniformFlowAtThousandResponseTimes) {
    // Haider–Levenspiel drag, a 1 µm particle (τ_St = 31 µs) in a flow that changes on a
    // 2 s scale, dt = 1000 τ_St: the particle must stay on the gas velocity (slip at most the
    // gas velocity change along one step) and bounded.
    Scene scene = singleParticleScene();
    scene.particles.radius.value = 1e-6;
    scene.time.integrator = GetParam();
    scene.nozzle.centre = Vec3(0.02, 0.01, 0);
    const double tau = stokesResponseTime(scene.particles.density, scene.particles.radius.value,
                                          scene.fluid.density, scene.fluid.kinematicViscosity);
    const test::SwirlingStagnationFlow flow(0.5, 0.3, Vec3(0.5, 0, 0));
    scene.time.dt = 1000 * tau;
    scene.time.endTime = 200 * scene.time.dt;
    Stepper stepper(scene, flow);
    CarrierSample gas;
    while (!stepper.finished()) {
        stepper.step();
        const Vec3 x = stepper.cloud().position.at(0);
        const Vec3 v = stepper.cloud().velocity.at(0);
        ASSERT_TRUE(x.allFinite() && v.allFinite());
        flow.sample(std::span(&x, 1), stepper.time(), {}, gas);
        // The step ends with v on the gas velocity at its start (e^(−1000) = 0); the particle
        // then moved |v| dt, so the slip is at most ‖∇U‖₂ |v| dt, with ‖∇U‖₂ = 0.8/s here.
        const double change = 0.8 * v.norm() * scene.time.dt;
        ASSERT_LT((v - gas.velocity[0]).norm(), change + 1e-12) << "t = " << stepper.time();
    }
}

INSTANTIATE_TEST_SUITE_P(Integrators, ExponentialIntegrator,
                         ::testing::Values(Integrator::exponentialEuler,
                                           Integrator::exponentialMidpoint));

} // namespace
} // namespace slides
