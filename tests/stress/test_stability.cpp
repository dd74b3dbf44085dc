// ctest-labels: stability
// Numerical stability under stress, each bounded in time:
//  - time steps from a hundredth to a thousand response times in a rotating flow: nothing
//    turns non-finite or leaves the flow, and once the step resolves the rotation the error
//    against a converged run shrinks at every tenfold smaller step (exponential integrators:
//    exact relaxation, stable for any dt/τ);
//  - particles a hundred times faster than the gas (high-Re drag): the slip decays
//    monotonically and never reverses, at steps of 0.02–20 response times;
//  - particles from 0.1 µm to 1 mm in one run (response times 1e-7 to 10 s): the smallest
//    follow the gas, the largest fly on, nothing turns non-finite;
//  - a dense pack (volume fraction 0.2) of elastic, frictionless spheres: impulse collisions
//    conserve kinetic energy and momentum to round-off over 100 steps with thousands of
//    contacts; inelastic ones never gain energy;
//  - a shear layer of 1 µm (gradient 1e7 1/s) crossed at 1 m/s: bounded velocities at any
//    step, errors that shrink as the step shrinks;
//  - a carrier that turns NaN stops the run with an error naming the particle;
//  - contact and Coulomb forces at a step a million times their stable one fling particles far
//    out of the domain, where they escape: the run goes on, no particle is lost.
#include "../support/test_scenes.h"
#include "slides/carrier/no_gas.h"
#include "slides/collide/particle_collisions.h"
#include "slides/core/name_table.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <utility>

namespace slides {
namespace {

/// One particle of radius R in the single-particle scene, started with the gas velocity plus
/// a cross-span speed.
Scene oneParticle(double radius, double crossSpanSpeed, double dt, double endTime) {
    Scene scene = test::singleParticleScene();
    scene.particles.radius.value = radius;
    scene.injection.crossSpanSpeed = crossSpanSpeed;
    scene.nozzle.centre = Vec3(0, 0.01, 0);
    scene.time.dt = dt;
    scene.time.endTime = endTime;
    return scene;
}

struct FinalState {
    Vec3 position, velocity;
};

FinalState runToEnd(const Scene& scene, const CarrierField& carrier) {
    Stepper stepper(scene, carrier);
    while (!stepper.finished()) stepper.step();
    EXPECT_EQ(stepper.cloud().size(), 1u);
    return {stepper.cloud().position.at(0), stepper.cloud().velocity.at(0)};
}

class StepSweep : public ::testing::TestWithParam<Integrator> {};

// 5 µm, ρp 2500 in air: τ_St = 0.19 ms; solid-body rotation at 20 rad/s for 0.5 s (2600 τ_St).
TEST_P(StepSweep, FromAHundredthToAThousandResponseTimesErrorsShrinkWithTheStep) {
    const double radius = 5e-6;
    const double tau = stokesResponseTime(2500, radius, 1.2, 1.5e-5);
    const test::SwirlingStagnationFlow rotation(0, 20, Vec3(0.5, 0, 0));
    Scene reference = oneParticle(radius, 0.3, tau / 200, 0.5);
    reference.time.integrator = Integrator::exponentialMidpoint;
    const FinalState exact = runToEnd(reference, rotation);
    double previousError = INFINITY;
    for (const double stepsPerTau : {1e-3, 1e-2, 1e-1, 1.0, 10.0, 1e2}) {
        Scene scene = oneParticle(radius, 0.3, tau / stepsPerTau, 0.5);
        scene.time.integrator = GetParam();
        const FinalState state = runToEnd(scene, rotation);
        ASSERT_TRUE(state.position.allFinite() && state.velocity.allFinite())
            << "dt = " << 1 / stepsPerTau << " τ";
        const double error = (state.position - exact.position).norm();
        // Once the step resolves the rotation (ω dt < 1; at 1000 τ, ω dt = 3.8).
        if (20 * scene.time.dt < 1) {
            EXPECT_LT(error, previousError) << "dt = " << 1 / stepsPerTau << " τ";
        }
        // Bounded even at a thousand response times: on the gas's circle within 0.5 m.
        EXPECT_LT(state.position.norm(), 1.0);
        previousError = error;
    }
    EXPECT_LT(previousError, 1e-4) << "at dt = τ/100";
}

INSTANTIATE_TEST_SUITE_P(ExponentialIntegrators, StepSweep,
                         ::testing::Values(Integrator::exponentialEuler,
                                           Integrator::exponentialMidpoint),
                         [](const auto& info) {
                             return std::string(nameOf(integratorNames(), info.param));
                         });

// 20 µm steel at 100 m/s across a 1 m/s stream: Re ≈ 270 at the start, τ ≈ 5 ms.
TEST(FastParticles, SlipDecaysMonotonicallyAndNeverReverses) {
    const test::UniformFlow stream(Vec3(1, 0, 0));
    for (const double dt : {1e-4, 1e-2, 0.1}) {
        Scene scene = oneParticle(20e-6, 100, dt, 2.0);
        scene.particles.density = 8000;
        scene.particles.count = 50;
        scene.nozzle.radius = 1e-3;
        Stepper stepper(scene, stream);
        stepper.step();
        std::vector<Vec3> firstSlip;
        for (const Vec3& v : stepper.cloud().velocity) firstSlip.push_back(Vec3(1, 0, 0) - v);
        std::vector<double> previous(firstSlip.size());
        for (std::size_t i = 0; i < firstSlip.size(); ++i) previous[i] = firstSlip[i].norm();
        while (!stepper.finished()) {
            stepper.step();
            const ParticleCloud& cloud = stepper.cloud();
            for (std::size_t i = 0; i < cloud.size(); ++i) {
                const Vec3 slip = Vec3(1, 0, 0) - cloud.velocity[i];
                ASSERT_TRUE(slip.allFinite());
                const std::size_t id = cloud.id[i];
                ASSERT_LE(slip.norm(), previous[id] * (1 + 1e-12)) << "dt " << dt;
                ASSERT_GE(slip.dot(firstSlip[id]), 0) << "the slip reversed at dt " << dt;
                previous[id] = slip.norm();
            }
        }
        for (const double slip : previous) EXPECT_LT(slip, 1e-6 * 100) << "dt " << dt;
    }
}

// Radii log-normal about 10 µm, geometric deviation 6, cut to [0.1 µm, 1 mm]: τ_St from
// 1e-7 s to 10 s in the rotating flow, at dt = 1e-4 s.
TEST(MixedSizes, SmallestFollowTheGasLargestFlyOnNothingNonFinite) {
    const test::SwirlingStagnationFlow rotation(0, 20, Vec3(0.5, 0, 0));
    Scene scene = oneParticle(1e-5, 0.3, 1e-4, 0.2);
    scene.particles.count = 2000;
    scene.nozzle.radius = 5e-3;
    RadiusDistribution& radius = scene.particles.radius = RadiusDistribution{};
    radius.kind = RadiusDistributionKind::logNormal;
    radius.median = 1e-5;
    radius.geometricStandardDeviation = 6.0;
    radius.minimum = 1e-7;
    radius.maximum = 1e-3;
    Stepper stepper(scene, rotation);
    while (!stepper.finished()) stepper.step();
    const ParticleCloud& cloud = stepper.cloud();
    ASSERT_EQ(cloud.size(), 2000u);
    CarrierSample gas;
    rotation.sample(cloud.position, 0, {}, gas);
    double smallest = INFINITY, largest = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        ASSERT_TRUE(cloud.position[i].allFinite() && cloud.velocity[i].allFinite());
        smallest = std::min(smallest, cloud.radius[i]);
        largest = std::max(largest, cloud.radius[i]);
        const double slip = (gas.velocity[i] - cloud.velocity[i]).norm();
        const double tau = stokesResponseTime(2500, cloud.radius[i], 1.2, 1.5e-5);
        // Slip in solid-body rotation (ω = 20 1/s about (0, 0.025)): the centripetal lag
        // τ ω² r, the start's 0.3 m/s decayed over 0.2 s, and the step's own lag behind the
        // gas at the step's end, ω |u| h (|u| < 1 m/s).
        const double radius = (cloud.position[i] - Vec3(0, 0.025, cloud.position[i].z())).norm();
        const double bound = tau * 400 * radius + 0.31 * std::exp(-0.2 / tau) + 20 * 1e-4;
        EXPECT_LE(slip, 1.01 * bound + 1e-12) << "radius " << cloud.radius[i];
    }
    EXPECT_LT(smallest, 5e-7);
    EXPECT_GT(largest, 2e-4);
}

/// A dense lattice of spheres (radius 50 µm, volume fraction about 0.2) moving at random.
ParticleCloud densePack(double speed) {
    ParticleCloud cloud;
    std::mt19937_64 generator(11);
    std::uniform_real_distribution<double> unit(-1, 1);
    const double spacing = 1.4e-4; // (4/3)π(50 µm)³ / (140 µm)³ = 0.19; gaps ≥ 10 µm
    ParticleId id = 0;
    for (int i = 0; i < 14; ++i)
        for (int j = 0; j < 14; ++j)
            for (int k = 0; k < 14; ++k) {
                const Vec3 x = Vec3(i, j, k) * spacing +
                               Vec3(unit(generator), unit(generator), unit(generator)) * 1.5e-5;
                const Vec3 v = Vec3(unit(generator), unit(generator), unit(generator)) * speed;
                cloud.add(id++, x, v, 50e-6);
                cloud.angularVelocity.push_back(Vec3::Zero());
            }
    return cloud;
}

double kineticEnergy(const ParticleCloud& cloud) { // per (4/3)πρ R³ / 2: equal spheres
    double sum = 0;
    for (const Vec3& v : cloud.velocity) sum += v.squaredNorm();
    return sum;
}

TEST(DensePack, ElasticCollisionsConserveEnergyInelasticNeverGainIt) {
    for (const double restitution : {1.0, 0.5}) {
        Scene scene = test::singleParticleScene();
        scene.collisions.model = CollisionModel::impulse;
        scene.collisions.restitution = {RestitutionModel::constant, restitution, 3};
        scene.collisions.friction = {0, 0};
        ParticleCloud cloud = densePack(1.0);
        ParticleCollisions collisions(scene.collisions, scene.particles);
        const double h = 2e-5; // 20 µm a step at 1 m/s, 0.4 radii
        const std::vector<double> steps(cloud.size(), h);
        const double energy0 = kineticEnergy(cloud);
        Vec3 momentum0 = Vec3::Zero();
        for (const Vec3& v : cloud.velocity) momentum0 += v;
        double previous = energy0;
        for (int step = 0; step < 100; ++step) {
            const std::vector<Vec3> start = cloud.position;
            for (std::size_t i = 0; i < cloud.size(); ++i)
                cloud.position[i] += h * cloud.velocity[i];
            collisions.collide(cloud, start, steps);
            const double energy = kineticEnergy(cloud);
            ASSERT_TRUE(std::isfinite(energy));
            ASSERT_LE(energy, previous * (1 + 1e-12)) << "step " << step << ", e " << restitution;
            previous = energy;
        }
        Vec3 momentum = Vec3::Zero();
        for (const Vec3& v : cloud.velocity) momentum += v;
        EXPECT_LT((momentum - momentum0).norm(), 1e-12 * std::sqrt(energy0 * cloud.size()));
        EXPECT_GT(collisions.collisions(), 1000) << "a dense pack";
        if (restitution == 1.0)
            EXPECT_NEAR(previous, energy0, 1e-11 * energy0) << "elastic: energy conserved";
        else
            EXPECT_LT(previous, 0.95 * energy0) << "inelastic: energy lost";
    }
}

/// U = (U0 tanh(y/δ), V, 0): a shear layer of thickness δ, crossed by a stream V.
class ShearLayer : public CarrierField {
public:
    ShearLayer(double speed, double thickness) : speed_(speed), thickness_(thickness) {}
    void sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                CarrierSample& out) const override {
        out.resize(points.size(), needs);
        for (std::size_t i = 0; i < points.size(); ++i) {
            const double y = points[i].y() / thickness_;
            out.velocity[i] = Vec3(speed_ * std::tanh(y), 1.0, 0);
            if (needs.velocityGradient) {
                out.velocityGradient[i].setZero();
                out.velocityGradient[i](0, 1) = speed_ / (thickness_ * std::cosh(y) * std::cosh(y));
            }
        }
    }
    std::string describe() const override { return "shear layer"; }

private:
    double speed_, thickness_;
};

// A 20 µm particle (τ_St ≈ 3.7 ms) started at y = −1 mm with the gas, carried at V = 1 m/s
// across a shear layer of 1 µm between −10 and +10 m/s.
TEST(SteepGradients, CrossingAMicrometreShearLayerStaysBoundedAndConverges) {
    const ShearLayer layer(10, 1e-6);
    const auto run = [&](double dt, Integrator integrator) {
        Scene scene = oneParticle(20e-6, 0, dt, 0.01);
        scene.nozzle.centre = Vec3(0, -1e-3, 0);
        scene.time.integrator = integrator;
        Stepper stepper(scene, layer);
        while (!stepper.finished()) stepper.step();
        return FinalState{stepper.cloud().position.at(0), stepper.cloud().velocity.at(0)};
    };
    const FinalState exact = run(1e-7, Integrator::exponentialMidpoint);
    double previous = INFINITY;
    for (const double dt : {1e-3, 1e-4, 1e-5, 1e-6}) {
        const FinalState state = run(dt, Integrator::exponentialMidpoint);
        ASSERT_TRUE(state.velocity.allFinite());
        EXPECT_LE(state.velocity.norm(), std::sqrt(101.0) * (1 + 1e-12))
            << "no faster than the gas";
        const double error = (state.position - exact.position).norm();
        EXPECT_LT(error, previous) << "dt " << dt;
        previous = error;
    }
}

/// Uniform flow that turns NaN beyond x = 0.05 m.
class BrokenFlow : public CarrierField {
public:
    void sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                CarrierSample& out) const override {
        out.resize(points.size(), needs);
        for (std::size_t i = 0; i < points.size(); ++i)
            out.velocity[i] = points[i].x() < 0.05 ? Vec3(1, 0, 0) : Vec3::Constant(NAN);
        for (auto& gradient : out.velocityGradient) gradient.setZero();
    }
    std::string describe() const override { return "broken flow"; }
};

TEST(BadCarrierValues, StopTheRunWithAnErrorNamingTheParticle) {
    const BrokenFlow broken;
    Scene scene = oneParticle(20e-6, 0, 1e-3, 1.0);
    scene.nozzle.centre = Vec3::Zero();
    Stepper stepper(scene, broken);
    try {
        while (!stepper.finished()) stepper.step();
        FAIL() << "a NaN gas velocity went unnoticed";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("particle 0 reached a non-finite state"),
                  std::string::npos)
            << error.what();
        EXPECT_LT(stepper.time(), 0.06) << "stopped where the gas turned NaN";
    }
}

/// 64 particles (R = 50 µm, ρp = 2500) at rest on a 4×4×4 lattice of 90 µm, every neighbour
/// overlapping by 10 µm, charged 1 mC each (a million times a real powder's charge), in a
/// 2 mm box without gas, stepped at 1 ms: a million Hertz contact times (≈ 1 ns) and far more
/// Coulomb times.
Scene flungApart(CollisionModel collisions, bool coulomb) {
    Scene scene = test::singleParticleScene();
    scene.carrier.type = CarrierType::none;
    scene.fluid = {0, 0, 293.15};
    scene.particles.count = 64;
    scene.particles.material = {1.6e11, 8e10};
    scene.collisions.model = collisions;
    scene.collisions.restitution = {RestitutionModel::constant, 0.5, 3};
    if (coulomb) {
        scene.physics.electromagnetic.model = ElectromagneticModel::lorentz;
        scene.physics.electromagnetic.chargeValue = 1e-3;
        scene.physics.electromagnetic.coulomb.model = CoulombModel::shifted;
        scene.physics.electromagnetic.coulomb.cutoff = 1e-3;
    }
    scene.domain = {Vec3::Constant(-1e-3), Vec3::Constant(1e-3)};
    scene.time.dt = 1e-3;
    scene.time.endTime = 1e-2;
    return scene;
}

class FlungApart : public ::testing::TestWithParam<std::pair<CollisionModel, bool>> {};

TEST_P(FlungApart, ParticlesFlungFarOutOfTheDomainEscapeAndNoneIsLost) {
    const auto [collisions, coulomb] = GetParam();
    const Scene scene = flungApart(collisions, coulomb);
    const NoGas vacuum;
    Stepper stepper(scene, vacuum);
    ParticleCloud cloud;
    for (int n = 0; n < 64; ++n) {
        const Vec3 site(n % 4 - 1.5, n / 4 % 4 - 1.5, n / 16 - 1.5);
        cloud.add(static_cast<ParticleId>(n), 90e-6 * site, Vec3::Zero(), 50e-6);
    }
    if (coulomb) cloud.charge.assign(64, 1e-3);
    RunCounters counters;
    counters.injected = 64;
    stepper.resume(counters, std::move(cloud), {});
    while (!stepper.finished()) stepper.step();
    EXPECT_GT(stepper.escaped(), 0) << "the test flings nothing out";
    EXPECT_EQ(stepper.escaped() + static_cast<long>(stepper.cloud().size()), 64);
    for (const Vec3& x : stepper.cloud().position) EXPECT_TRUE(insideBox(scene.domain, x));
}

INSTANTIATE_TEST_SUITE_P(ContactAndCoulombForces, FlungApart,
                         ::testing::Values(std::pair{CollisionModel::softSphere, false},
                                           std::pair{CollisionModel::none, true},
                                           std::pair{CollisionModel::softSphere, true}),
                         [](const auto& info) {
                             return std::string(info.param.first == CollisionModel::softSphere
                                                    ? "softSpheres"
                                                    : "") +
                                    (info.param.second ? "Coulomb" : "");
                         });

} // namespace
} // namespace slides
