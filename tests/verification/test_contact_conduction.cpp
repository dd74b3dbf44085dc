// ctest-labels: collision conduction
// Conduction between touching soft spheres (physics/contact_conduction.h, Eq. 2.118 of
// Batchelor & O'Brien 1977) through the soft-sphere contacts (collide/soft_sphere_collisions.h):
//  - the conductance π K_f a ln(K_p/K_f)² with a = 2R*, zero where K_p ≤ K_f and when off;
//  - two touching spheres at 400 and 300 K relax to their heat-capacity-weighted mean as
//    exp(−H (1/(m₁c) + 1/(m₂c)) t): each explicit step multiplies the difference by exactly
//    1 − H dt (1/(m₁c) + 1/(m₂c)) (to round-off), and the continuous rate is met to O(dt);
//  - a packed bed (a 7×7×7 lattice of touching spheres of two sizes, random temperatures, no
//    gas exchange) keeps Σ m c T to round-off while its temperatures spread out and even;
//  - the same numbers for one and two threads.
// The spheres stay where they are (only the loads are computed, never applied).
#include "slides/collide/soft_sphere_collisions.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace slides {
namespace {

constexpr double specificHeat = 900; // c [J/(kg K)]: alumina-like
constexpr double density = 3900;     // [kg/m³]
constexpr double conductivity = 30;  // K_p [W/(m K)]
constexpr double gasConductivity = 0.0257;

ContactConductionSettings batchelorOBrien() {
    return {ContactConduction::batchelorOBrien, conductivity, gasConductivity};
}

SoftSphereCollisions collisionsOf(const ContactConductionSettings& conduction) {
    CollisionSettings collisions;
    collisions.model = CollisionModel::softSphere;
    collisions.restitution = {RestitutionModel::constant, 1.0, 3};
    collisions.heating = false; // conduction alone
    collisions.conduction = conduction;
    ParticleSettings particles;
    particles.density = density;
    particles.specificHeat = specificHeat;
    particles.material = {1.6e11, 8e10}; // K, G
    return SoftSphereCollisions(collisions, particles, {},
                                Box{Vec3::Constant(-1), Vec3::Constant(1)});
}

/// A cloud at rest with temperatures, ready for updateLoads.
void prepare(ParticleCloud& cloud) {
    cloud.angularVelocity.assign(cloud.size(), Vec3::Zero());
    cloud.contactForce.assign(cloud.size(), Vec3::Zero());
    cloud.contactTorque.assign(cloud.size(), Vec3::Zero());
}

double heatContent(const ParticleCloud& cloud) {
    double total = 0;
    for (std::size_t i = 0; i < cloud.size(); ++i)
        total += sphereMass(cloud.radius[i], density) * specificHeat * cloud.temperature[i];
    return total;
}

TEST(ContactConductance, BatchelorOBrienOfTheSphereRadius) {
    const double radius = 1e-3; // equal spheres: R* = R/2
    const double expected = std::numbers::pi * gasConductivity * radius *
                            std::log(std::pow(conductivity / gasConductivity, 2));
    EXPECT_NEAR(contactConductance(batchelorOBrien(), radius / 2) / expected, 1.0, 1e-15);
    EXPECT_EQ(contactConductance({}, radius / 2), 0.0);
    EXPECT_EQ(
        contactConductance({ContactConduction::batchelorOBrien, 0.02, gasConductivity}, radius / 2),
        0.0);
}

TEST(ContactConduction, TouchingPairRelaxesToTheMeanAtTheRateOfEquation2118) {
    const double small = 1e-3, large = 2e-3;
    ParticleCloud cloud;
    cloud.add(0, Vec3::Zero(), Vec3::Zero(), small);
    cloud.add(1, Vec3(small + large - 1e-6, 0, 0), Vec3::Zero(), large);
    prepare(cloud);
    cloud.temperature = {400, 300};
    SoftSphereCollisions collisions = collisionsOf(batchelorOBrien());
    const double m1 = sphereMass(small, density), m2 = sphereMass(large, density);
    const double conductance =
        contactConductance(batchelorOBrien(), small * large / (small + large));
    const double rate = conductance * (1 / (m1 * specificHeat) + 1 / (m2 * specificHeat));
    const double mean = (m1 * 400 + m2 * 300) / (m1 + m2);
    const double dt = 1e-3 / rate; // a thousandth of the relaxation time
    const double heat = heatContent(cloud);
    double difference = 100;
    for (int n = 1; n <= 3000; ++n) {
        collisions.updateLoads(cloud, dt);
        difference *= 1 - rate * dt; // the explicit step, exactly
        ASSERT_NEAR(cloud.temperature[0] - cloud.temperature[1], difference, 1e-11) << n;
    }
    // Three relaxation times: e⁻³ of the difference is left, to O(rate dt) = 1e-3 of it.
    EXPECT_NEAR(difference / (100 * std::exp(-3.0)), 1.0, 2e-3);
    EXPECT_NEAR((m1 * cloud.temperature[0] + m2 * cloud.temperature[1]) / (m1 + m2), mean, 1e-11);
    EXPECT_NEAR(heatContent(cloud) / heat, 1.0, 1e-13); // 3000 steps' round-off: 1.8e-15
    // Apart, nothing flows; off, nothing flows.
    cloud.position[1].x() += 1e-5;
    const double before = cloud.temperature[0];
    collisions.updateLoads(cloud, dt);
    EXPECT_EQ(cloud.temperature[0], before);
    cloud.position[1].x() -= 1e-5;
    SoftSphereCollisions off = collisionsOf({});
    off.updateLoads(cloud, dt);
    EXPECT_EQ(cloud.temperature[0], before);
}

/// A 7×7×7 simple-cubic bed (more particles than one thread's batch) of touching spheres, radii 1
/// and 1.2 mm alternating along x, the temperatures random in [300, 500] K; steps of updateLoads at
/// the given thread count.
ParticleCloud packedBed(int steps, int threads) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
    ParticleCloud cloud;
    std::mt19937_64 generator(3);
    std::uniform_real_distribution<double> temperature(300, 500);
    const double pitch = 2.2e-3 - 2e-6; // the two radii less a small overlap
    for (int k = 0; k < 343; ++k) {
        const int i = k % 7, j = k / 7 % 7, l = k / 49;
        cloud.add(static_cast<ParticleId>(k), pitch * Vec3(i, j, l), Vec3::Zero(),
                  (i + j + l) % 2 == 0 ? 1e-3 : 1.2e-3);
    }
    prepare(cloud);
    for (std::size_t i = 0; i < cloud.size(); ++i)
        cloud.temperature.push_back(temperature(generator));
    SoftSphereCollisions collisions = collisionsOf(batchelorOBrien());
    // A step of 0.2 s moves a particle's temperature by H dt/(m c) ≈ 1.7 % per neighbour.
    for (int n = 0; n < steps; ++n) collisions.updateLoads(cloud, 0.2);
#ifdef _OPENMP
    omp_set_num_threads(omp_get_num_procs());
#endif
    return cloud;
}

double spread(const ParticleCloud& cloud) {
    const auto [lowest, highest] =
        std::minmax_element(cloud.temperature.begin(), cloud.temperature.end());
    return *highest - *lowest;
}

TEST(ContactConduction, PackedBedConservesItsHeatToRoundOffAndEvensOut) {
    const ParticleCloud start = packedBed(0, 2);
    const ParticleCloud bed = packedBed(200, 2);
    // 343 particles at ~400 K: the sum of heat contents drifts by round-off only (each step
    // adds 1e-16 relative per particle at most).
    EXPECT_NEAR(heatContent(bed) / heatContent(start), 1.0, 1e-12);
    EXPECT_LT(spread(bed), 0.5 * spread(start));
    for (const double t : bed.temperature) {
        EXPECT_GT(t, 300);
        EXPECT_LT(t, 500);
    }
}

TEST(ContactConduction, PackedBedIsTheSameForAnyThreadCount) {
    EXPECT_EQ(packedBed(50, 1).temperature, packedBed(50, 2).temperature);
}

} // namespace
} // namespace slides
