// ctest-labels: collision
// Impulse–momentum collisions (collide-and-stream, Section 2.3–2.4 of the reference):
//  - a pair impulse (Eq. 2.34–2.58) conserves linear and angular momentum to round-off, sends
//    the normal relative velocity to −e times itself (Eq. 2.20) and, without friction, loses
//    exactly ½ m* (1 − e²) v_n² of kinetic energy;
//  - oblique impacts on a wall through the whole stepper, over incidence angles on both sides
//    of the stick–slip transition tan θ = (7/2) μ (1 + e), against the rigid-body solution
//    (Eq. 2.25, 2.29–2.33; Walton 1993, the rigid limit of Maw, Barber & Fawcett 1976):
//    stick: v_t' = (5/7) v_t, ωR = (5/7) v_t (rolling); slip: v_t' = v_t − μ(1 + e) v_n,
//    ωR = (5/2) μ (1 + e) v_n; and v_n' = e v_n;
//  - velocity-dependent restitution (Eq. 2.62–2.63): elastic below the yield velocity, Johnson's
//    e ∝ v^(−1/4) above, the value for Table 5.2's particle on its target worked by hand;
//  - a dense cloud's collide step conserves momentum and gives bit-identical results on 1 and
//    2 threads.
#include "../support/test_scenes.h"
#include "slides/collide/impulse.h"
#include "slides/collide/particle_collisions.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/restitution.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace slides {
namespace {

constexpr double pi = std::numbers::pi;

double sphereMass(double radius, double density) {
    return 4.0 / 3.0 * pi * std::pow(radius, 3) * density;
}

/// Linear momentum and angular momentum about the origin (orbital + spin, I = 2/5 m R²) of
/// two bodies at the given centres.
std::pair<Vec3, Vec3> momenta(const ImpactBody& a, const Vec3& xa, const ImpactBody& b,
                              const Vec3& xb) {
    const auto body = [](const ImpactBody& k, const Vec3& x) {
        const double m = 1 / k.inverseMass;
        return std::pair<Vec3, Vec3>{m * k.velocity,
                                     m * x.cross(k.velocity) +
                                         0.4 * m * k.radius * k.radius * k.angularVelocity};
    };
    const auto [pa, la] = body(a, xa);
    const auto [pb, lb] = body(b, xb);
    return {pa + pb, la + lb};
}

TEST(PairImpulse, ConservesMomentaAndRestoresTheNormalVelocityByE) {
    // Random oblique impacts of unequal spinning spheres, sticking and slipping. Round-off
    // of the momenta: a few ulps of the largest term (|m v| ≈ 1e-8 kg m/s here).
    std::mt19937_64 generator(3);
    std::uniform_real_distribution<double> unit(-1, 1);
    const FrictionSettings friction{0.4, 0.3};
    int slipping = 0, sticking = 0;
    for (int trial = 0; trial < 200; ++trial) {
        const double ra = 80e-6, rb = 50e-6, e = 0.7;
        const Vec3 normal = Vec3(unit(generator), unit(generator), unit(generator)).normalized();
        const Vec3 xb(1e-3, 2e-3, 3e-3);
        const Vec3 xa = xb + (ra + rb) * normal;
        ImpactBody a{Vec3(unit(generator), unit(generator), unit(generator)) * 10,
                     Vec3(unit(generator), unit(generator), unit(generator)) * 1e5,
                     1 / sphereMass(ra, 5680), ra};
        ImpactBody b{Vec3(unit(generator), unit(generator), unit(generator)) * 10,
                     Vec3(unit(generator), unit(generator), unit(generator)) * 1e5,
                     1 / sphereMass(rb, 2500), rb};
        const double approach = (a.velocity - b.velocity).dot(normal);
        if (approach >= 0) continue;
        const auto [p0, l0] = momenta(a, xa, b, xb);
        const Vec3 impulse = contactImpulse(a, b, normal, e, friction);
        const Vec3 tangential = impulse - impulse.dot(normal) * normal;
        const bool slips =
            std::abs(tangential.norm() - friction.dynamicCoefficient * impulse.dot(normal)) <
            1e-12 * impulse.norm();
        (slips ? slipping : sticking)++;
        applyImpulse(a, b, normal, impulse);
        const auto [p1, l1] = momenta(a, xa, b, xb);
        EXPECT_LT((p1 - p0).norm(), 1e-14 * p0.norm() + 1e-22);
        EXPECT_LT((l1 - l0).norm(), 1e-13 * (l0.norm() + 1e-14));
        EXPECT_NEAR((a.velocity - b.velocity).dot(normal), -e * approach, 1e-12 * -approach);
    }
    EXPECT_GT(sticking, 20);
    EXPECT_GT(slipping, 20);
}

TEST(PairImpulse, FrictionlessEnergyLossIsThatOfTheRestitution) {
    // ΔKE = −½ m* (1 − e²) v_n² for any tangential velocity when μ = 0.
    const double ra = 80e-6, rb = 40e-6, e = 0.55;
    const double ma = sphereMass(ra, 5680), mb = sphereMass(rb, 5680);
    ImpactBody a{Vec3(3, 4, 0), Vec3::Zero(), 1 / ma, ra};
    ImpactBody b{Vec3(-2, 1, 1), Vec3::Zero(), 1 / mb, rb};
    const Vec3 normal = Vec3(-1, 0.2, 0).normalized();
    const double vn = (a.velocity - b.velocity).dot(normal);
    const auto energy = [&] {
        return 0.5 * ma * a.velocity.squaredNorm() + 0.5 * mb * b.velocity.squaredNorm();
    };
    const double before = energy();
    applyImpulse(a, b, normal, contactImpulse(a, b, normal, e, FrictionSettings{0, 0}));
    const double reduced = ma * mb / (ma + mb);
    EXPECT_NEAR(before - energy(), 0.5 * reduced * (1 - e * e) * vn * vn, 1e-12 * before);
}

struct ObliqueImpact {
    const char* name;
    double incidenceDegrees; ///< from the wall normal
};

class ObliqueWallImpact : public ::testing::TestWithParam<ObliqueImpact> {};

TEST_P(ObliqueWallImpact, MatchesTheRigidBodyStickSlipSolution) {
    // A 50 µm sphere flies at 10 m/s through a gas too thin to drag it (ρf = 1e-12: the
    // velocity changes by < 1e-12 relative over the flight) onto a rebound wall, touching
    // mid-step. Constant e = 0.6 and μ = 0.2: stick below tan θ = 3.5·0.2·1.6 = 1.12 (48.2°).
    Scene scene = test::singleParticleScene();
    scene.fluid.density = 1e-12;
    const double e = 0.6, mu = 0.2, speed = 10;
    scene.collisions.restitution = {RestitutionModel::constant, e, 3};
    scene.collisions.friction = {mu, mu};
    const double theta = GetParam().incidenceDegrees * pi / 180;
    const double vn = speed * std::cos(theta), vt = speed * std::sin(theta);
    const double radius = scene.particles.radius.value;
    scene.time.dt = 1e-4;
    scene.time.endTime = 3e-4;
    // Wall at x = R + 1.5 dt·vn: the touch falls at the middle of the second step.
    Surface wall;
    wall.name = "wall";
    wall.point = Vec3(radius + 1.5 * scene.time.dt * vn, 0, 0);
    wall.normal = Vec3(-1, 0, 0);
    wall.interaction = SurfaceInteraction::rebound;
    scene.surfaces.push_back(wall);
    const test::UniformFlow gas(Vec3(vn, vt, 0));
    Stepper stepper(scene, gas);
    stepper.step();
    stepper.step();
    ASSERT_EQ(stepper.cloud().size(), 1u);
    const Vec3 v = stepper.cloud().velocity[0];
    const Vec3 spin = stepper.cloud().angularVelocity[0];
    const bool slips = std::tan(theta) > 3.5 * mu * (1 + e);
    const double vtAfter = slips ? vt - mu * (1 + e) * vn : 5.0 / 7.0 * vt;
    const double spinAfter = slips ? 2.5 * mu * (1 + e) * vn / radius : 5.0 / 7.0 * vt / radius;
    const double tolerance = 1e-9 * speed; // the thin gas's drag over 2 steps, and round-off
    EXPECT_NEAR(v.x(), -e * vn, tolerance);
    EXPECT_NEAR(v.y(), vtAfter, tolerance);
    EXPECT_NEAR(spin.z() * radius, -spinAfter * radius, tolerance);
    EXPECT_NEAR(std::atan2(v.y(), -v.x()), std::atan2(vtAfter, e * vn), 1e-9);
    EXPECT_EQ(stepper.surfaceImpacts().rebounds()[0], 1u);
    // After the touch the sphere flies the rest of the step with its new velocity: it is back
    // at its touch point's height minus half a step of rebound.
    const double touchX = wall.point.x() - radius;
    EXPECT_NEAR(stepper.cloud().position[0].x(), touchX - 0.5 * scene.time.dt * e * vn, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Angles, ObliqueWallImpact,
                         ::testing::Values(ObliqueImpact{"normal", 0}, ObliqueImpact{"deg10", 10},
                                           ObliqueImpact{"deg30", 30}, ObliqueImpact{"deg45", 45},
                                           ObliqueImpact{"deg50", 50}, ObliqueImpact{"deg60", 60},
                                           ObliqueImpact{"deg80", 80}),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(VelocityDependentRestitution, ElasticBelowYieldAndJohnsonScalingAbove) {
    // Table 5.2: particle K = 167 GPa, G = 77 GPa, Y = 200 MPa, R = 80 µm, ρ = 5680; target
    // K = 160 GPa, G = 80 GPa. By hand: E = 200.2 / 205.7 GPa, ν = 0.3003 / 0.2857,
    // E* = 111.0 GPa, m = 1.2182e-8 kg, v_Y = 0.01482 m/s (Eq. 2.63, α = 3),
    // e(20 m/s) = 1.88·3^(5/8)·√(Y/E*)·(½mv²/(YR³))^(−1/8) = 0.25302.
    MaterialSettings particle{167e9, 77e9, 200e6, 0.046};
    MaterialSettings target{160e9, 80e9, 0, 1.1};
    const double radius = 80e-6, mass = sphereMass(radius, 5680);
    const ContactPair pair = contactPair({mass, radius, &particle}, {INFINITY, INFINITY, &target});
    EXPECT_NEAR(pair.youngsModulus / 111.0048e9, 1.0, 1e-5);
    EXPECT_DOUBLE_EQ(pair.mass, mass);
    EXPECT_DOUBLE_EQ(pair.radius, radius);
    const RestitutionSettings settings{RestitutionModel::velocityDependent, 0, 3};
    EXPECT_NEAR(yieldVelocity(pair, 3), 0.0148175, 1e-6);
    EXPECT_EQ(restitutionCoefficient(settings, pair, 0.01), 1.0);
    EXPECT_NEAR(restitutionCoefficient(settings, pair, 20), 0.253016, 1e-5);
    // e ∝ v^(−1/4) (Johnson 1985, §11.4): exact in the plastic range.
    EXPECT_NEAR(restitutionCoefficient(settings, pair, 40) /
                    restitutionCoefficient(settings, pair, 2.5),
                std::pow(16.0, -0.25), 1e-12);
    // Continuous: e reaches 1 from below where 1.88 (v/v_Y)^(−1/4)·5.1^(−1/8) = 1.
    const double joins = yieldVelocity(pair, 3) * std::pow(1.88 * std::pow(5.1, -0.125), 4);
    EXPECT_NEAR(restitutionCoefficient(settings, pair, joins * 1.0001), 1.0, 1e-4);
    EXPECT_EQ(restitutionCoefficient(settings, pair, joins * 0.999), 1.0);
}

/// A dense box of particles moving at random: many contacts in one step, some particles in
/// several.
ParticleCloud denseCloud(std::vector<Vec3>& start, double h) {
    ParticleCloud cloud;
    std::mt19937_64 generator(5);
    std::uniform_real_distribution<double> unit(-1, 1);
    for (ParticleId id = 0; id < 3000; ++id) {
        const Vec3 x = Vec3(unit(generator), unit(generator), unit(generator)) * 2e-3;
        const Vec3 v = Vec3(unit(generator), unit(generator), unit(generator)) * 5;
        cloud.add(id, x + h * v, v, 50e-6 + 30e-6 * unit(generator));
        cloud.angularVelocity.push_back(Vec3::Zero());
        start.push_back(x);
    }
    return cloud;
}

TEST(CloudCollisions, ConserveMomentumAndDoNotDependOnThreads) {
    Scene scene = test::singleParticleScene();
    scene.particles.density = 2500;
    scene.collisions.model = CollisionModel::impulse;
    scene.collisions.restitution = {RestitutionModel::constant, 0.8, 3};
    const double h = 2e-5;
    const std::vector<double> steps(3000, h);
    ParticleCloud runs[2];
    long contacts[2] = {0, 0};
    for (int threads = 1; threads <= 2; ++threads) {
#ifdef _OPENMP
        omp_set_num_threads(threads);
#endif
        std::vector<Vec3> start;
        ParticleCloud cloud = denseCloud(start, h);
        Vec3 momentum0 = Vec3::Zero();
        for (std::size_t i = 0; i < cloud.size(); ++i)
            momentum0 += std::pow(cloud.radius[i], 3) * cloud.velocity[i];
        ParticleCollisions collisions(scene.collisions, scene.particles);
        collisions.collide(cloud, start, steps);
        Vec3 momentum1 = Vec3::Zero();
        for (std::size_t i = 0; i < cloud.size(); ++i)
            momentum1 += std::pow(cloud.radius[i], 3) * cloud.velocity[i];
        // Momentum in units of (4/3)πρ: round-off of 3000 terms of at most (80 µm)³·5√3 m/s.
        EXPECT_LT((momentum1 - momentum0).norm(), 1e-13 * 3000 * std::pow(80e-6, 3) * 5);
        contacts[threads - 1] = collisions.collisions();
        runs[threads - 1] = std::move(cloud);
    }
#ifdef _OPENMP
    omp_set_num_threads(omp_get_num_procs());
#endif
    EXPECT_GT(contacts[0], 100);
    EXPECT_EQ(contacts[0], contacts[1]);
    EXPECT_EQ(runs[0].velocity, runs[1].velocity);
    EXPECT_EQ(runs[0].position, runs[1].position);
    EXPECT_EQ(runs[0].angularVelocity, runs[1].angularVelocity);
}

TEST(CollisionalHeating, PairContactsTurnTheEnergyTheyDissipateIntoHeat) {
    // Eq. 2.115–2.117: all the kinetic energy (translation and spin) a contact dissipates
    // becomes heat, m c Δθ summed over the cloud; a pair shares it by heat capacity.
    Scene scene = test::singleParticleScene();
    scene.collisions.model = CollisionModel::impulse;
    scene.collisions.restitution = {RestitutionModel::constant, 0.6, 3};
    scene.particles.specificHeat = 460;
    const double h = 2e-5;
    std::vector<Vec3> start;
    ParticleCloud cloud = denseCloud(start, h);
    cloud.temperature.assign(cloud.size(), 300.0);
    const auto kinetic = [&](const ParticleCloud& c) {
        double energy = 0;
        for (std::size_t i = 0; i < c.size(); ++i) {
            const double mass = sphereMass(c.radius[i], scene.particles.density);
            energy += 0.5 * mass *
                      (c.velocity[i].squaredNorm() +
                       0.4 * c.radius[i] * c.radius[i] * c.angularVelocity[i].squaredNorm());
        }
        return energy;
    };
    const double before = kinetic(cloud);
    ParticleCollisions collisions(scene.collisions, scene.particles);
    collisions.collide(cloud, start, std::vector<double>(cloud.size(), h));
    double heat = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i)
        heat += sphereMass(cloud.radius[i], scene.particles.density) * 460 *
                (cloud.temperature[i] - 300);
    ASSERT_GT(collisions.collisions(), 100);
    EXPECT_GT(heat, 0.02 * before); // measured 6 %: not every particle collides
    // Energy conserved to the round-off of sums over 3000 particles.
    EXPECT_NEAR(kinetic(cloud) + heat, before, 1e-12 * before);
}

} // namespace
} // namespace slides
