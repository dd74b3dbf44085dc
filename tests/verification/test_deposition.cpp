// ctest-labels: deposition
// Deposition (Section 5.3.2 of the reference) through the whole stepper, for Table 5.2's
// particle (R = 80 µm, ρ = 5680, K = 167 GPa, G = 77 GPa, Y = 200 MPa, γ = 0.046 J/m²) on its
// target (K = 160 GPa, G = 80 GPa, γ = 1.1 J/m²) with α_adh = 5000 and α = 3:
//  - Eq. 5.9: v_crit = 0.2 F_adh δt₁ / m, F_adh = α_adh 2πR·2√(γ₁γ₂) = 1.13069 N,
//    δt₁ = √(πm/(8RαY)) = 3.15691e-7 s (Eq. 2.64), m = 1.21817e-8 kg → v_crit = 5.86045 m/s
//    (worked by hand); particles 1 % below stick, 1 % above rebound with e of Eq. 2.62;
//  - the deposit is an obstacle: a second particle on the same path meets the stuck one
//    (rigid, so m* = m, R* = R/2: v_crit = 0.847420 m/s for γ₁ = γ₂ = 0.046) and sticks on top
//    of it below that speed, rebounds off it above.
#include "../support/gas_scenes.h"
#include "../support/test_scenes.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slides {
namespace {

/// Table 5.2's particles flying at `speed` along +x through a gas too thin to drag them
/// (ρf = 1e-12), from a point nozzle 2 mm before a deposit target; `count` particles
/// injected 1 ms apart.
Scene depositionScene(double speed, long count) {
    Scene scene = test::singleParticleScene();
    scene.fluid.density = 1e-12;
    scene.particles.count = count;
    scene.particles.density = 5680;
    scene.particles.radius.value = 80e-6;
    scene.particles.material = {167e9, 77e9, 200e6, 0.046};
    scene.injection.mode = InjectionMode::rate;
    scene.injection.rate = 1e3;
    scene.deposition.factor = 5000;
    scene.collisions.restitution = {RestitutionModel::velocityDependent, 0, 3};
    Surface target;
    target.name = "target";
    target.point = Vec3(2e-3, 0, 0);
    target.normal = Vec3(-1, 0, 0);
    target.material = {160e9, 80e9, 0, 1.1};
    target.interaction = SurfaceInteraction::deposit;
    scene.surfaces.push_back(target);
    scene.time.dt = 1e-5;
    scene.time.endTime = static_cast<double>(count) * 1e-3 + 2e-3 / speed + 1e-4;
    return scene;
}

struct Outcome {
    std::size_t stuck;
    std::vector<Vec3> velocities; ///< of the particles still flying
    std::vector<Arrival> arrivals;
};

Outcome run(double speed, long count) {
    const Scene scene = depositionScene(speed, count);
    const test::UniformFlow gas(Vec3(speed, 0, 0));
    Stepper stepper(scene, gas);
    while (!stepper.finished()) stepper.step();
    return {stepper.surfaceImpacts().deposit().size(), stepper.cloud().velocity,
            stepper.arrivals()};
}

constexpr double criticalSpeed = 5.86045; // Eq. 5.9, worked by hand above

TEST(DepositionCriterion, StickJustBelowTheCriticalSpeedOfEquation59) {
    const Outcome below = run(0.99 * criticalSpeed, 1);
    ASSERT_EQ(below.stuck, 1u);
    ASSERT_EQ(below.arrivals.size(), 1u);
    EXPECT_NEAR(below.arrivals[0].position.x(), 2e-3 - 80e-6, 1e-12);
    EXPECT_NEAR(below.arrivals[0].velocity.x(), 0.99 * criticalSpeed, 1e-9);
}

TEST(DepositionCriterion, ReboundJustAboveItWithTheRestitutionOfEquation262) {
    const double speed = 1.01 * criticalSpeed;
    const Outcome above = run(speed, 1);
    EXPECT_EQ(above.stuck, 0u);
    ASSERT_EQ(above.velocities.size(), 1u);
    // e = 1.88·3^(5/8)·√(Y/E*)·(½mv²/(YR³))^(−1/8) at v = 5.91905 m/s: 0.343038 (by hand,
    // E* = 111.0048 GPa).
    EXPECT_NEAR(-above.velocities[0].x() / speed, 0.343038, 2e-6);
}

TEST(DepositGrowth, SecondParticleSticksOnTheFirstWhenSlow) {
    // 0.5 m/s: both below their limits (5.86 on the target, 0.847 on the deposit).
    const Outcome slow = run(0.5, 2);
    ASSERT_EQ(slow.stuck, 2u);
    ASSERT_EQ(slow.arrivals.size(), 2u);
    // The second sits on the first: centre one diameter further from the target.
    EXPECT_NEAR(slow.arrivals[1].position.x(), slow.arrivals[0].position.x() - 160e-6, 1e-12);
}

TEST(DepositGrowth, SecondParticleReboundsOffTheFirstAboveTheParticleParticleLimit) {
    // 1.2 m/s: sticks on the target (< 5.86), rebounds off the deposit (> 0.847).
    const Outcome fast = run(1.2, 2);
    EXPECT_EQ(fast.stuck, 1u);
    ASSERT_EQ(fast.velocities.size(), 1u);
    EXPECT_LT(fast.velocities[0].x(), 0); // flying back, head-on: the point nozzle's 1e-15 m
    EXPECT_NEAR(fast.velocities[0].y(), 0, 1e-10); // spread tilts the normal by ~1e-11 rad
    // Just below the limit it sticks.
    EXPECT_EQ(run(0.99 * 0.847420, 2).stuck, 2u);
    EXPECT_EQ(run(1.01 * 0.847420, 2).stuck, 1u);
}

/// What became of the first particle of depositionScene at `speed` with its temperature
/// tracked (gas and particle at 300 K, so convection adds nothing): stepped until it arrives
/// or turns back.
struct HeatedImpact {
    std::vector<Arrival> arrivals;
    double velocity = 0;    ///< along the flight, if still flying [m/s]
    double temperature = 0; ///< if still flying [K]
};

HeatedImpact heatedImpact(double speed) {
    Scene scene = depositionScene(speed, 1);
    scene.physics.heatTransfer = HeatTransferModel::ranzMarshall;
    scene.particles.specificHeat = 460;
    scene.particles.injectionTemperature = 300;
    scene.fluid.temperature = 300;
    scene.fluid.thermalConductivity = 0.0257;
    scene.fluid.specificHeat = 1005;
    const test::UniformTurbulentGas gas(0.0, 0.0, 300, Vec3(speed, 0, 0));
    Stepper stepper(scene, gas);
    while (!stepper.finished() && stepper.arrivals().empty() &&
           (stepper.cloud().empty() || stepper.cloud().velocity[0].x() > 0))
        stepper.step();
    HeatedImpact impact{stepper.arrivals()};
    if (!stepper.cloud().empty()) {
        impact.velocity = stepper.cloud().velocity[0].x();
        impact.temperature = stepper.cloud().temperature[0];
    }
    return impact;
}

TEST(CollisionalHeating, StickingTurnsTheImpactEnergyIntoHeat) {
    // Eq. 2.117 with ΔH the whole ½mv² the particle arrives with: Δθ = v²/(2c).
    const double speed = 0.99 * criticalSpeed;
    const HeatedImpact impact = heatedImpact(speed);
    ASSERT_EQ(impact.arrivals.size(), 1u);
    EXPECT_NEAR(impact.arrivals[0].temperature, 300 + speed * speed / (2 * 460), 1e-12 * 300);
}

TEST(CollisionalHeating, ReboundTurnsTheLostEnergyIntoHeat) {
    // Head-on rebound with e = 0.343038 (Eq. 2.62, above): Δθ = (1 − e²) v²/(2c).
    const double speed = 1.01 * criticalSpeed;
    const HeatedImpact impact = heatedImpact(speed);
    ASSERT_EQ(impact.arrivals.size(), 0u);
    const double rebound = -impact.velocity;
    EXPECT_NEAR(rebound / speed, 0.343038, 2e-6);
    EXPECT_NEAR(impact.temperature, 300 + (speed * speed - rebound * rebound) / (2 * 460),
                1e-12 * 300);
}

} // namespace
} // namespace slides
