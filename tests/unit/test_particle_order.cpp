// ctest-labels: unit foundation
// The cloud ordered by carrier location (core/particle_order.h): every array, and the model
// state of stateWidth entries a particle, moves with its particle to the order of ascending
// (location, id), at step counts that are multiples of particleOrderInterval only; and by the
// soft-sphere contact grid's cells (collide/soft_sphere_collisions.h, cellOrder).
#include "slides/collide/soft_sphere_collisions.h"
#include "slides/core/particle_order.h"

#include <gtest/gtest.h>

namespace slides {
namespace {

ParticleCloud cloudOfSix() {
    ParticleCloud cloud;
    cloud.stateWidth = 2;
    const std::int32_t locations[] = {5, -1, 5, 2, -3, 2};
    const ParticleId ids[] = {10, 11, 9, 12, 13, 8};
    for (int k = 0; k < 6; ++k) {
        const double n = static_cast<double>(ids[k]);
        cloud.add(ids[k], Vec3(n, 0, 0), Vec3(0, n, 0), n * 1e-6);
        cloud.carrierLocation.push_back(locations[k]);
        cloud.temperature.push_back(300 + n);
        cloud.modelState[2 * k] = n;
        cloud.modelState[2 * k + 1] = -n;
    }
    return cloud;
}

TEST(ParticleOrder, SortsEveryArrayByLocationThenId) {
    ParticleCloud cloud = cloudOfSix();
    orderByLocation(cloud, 2 * particleOrderInterval);
    const std::vector<ParticleId> ids{13, 11, 8, 12, 9, 10};
    const std::vector<std::int32_t> locations{-3, -1, 2, 2, 5, 5};
    EXPECT_EQ(cloud.id, ids);
    EXPECT_EQ(cloud.carrierLocation, locations);
    for (std::size_t k = 0; k < cloud.size(); ++k) {
        const double n = static_cast<double>(cloud.id[k]);
        EXPECT_EQ(cloud.position[k], Vec3(n, 0, 0));
        EXPECT_EQ(cloud.velocity[k], Vec3(0, n, 0));
        EXPECT_EQ(cloud.radius[k], n * 1e-6);
        EXPECT_EQ(cloud.temperature[k], 300 + n);
        EXPECT_EQ(cloud.modelState[2 * k], n);
        EXPECT_EQ(cloud.modelState[2 * k + 1], -n);
    }
    EXPECT_TRUE(cloud.eddy.empty()); // arrays of models that are off stay empty
}

TEST(ParticleOrder, LeavesTheCloudBetweenReorderSteps) {
    ParticleCloud cloud = cloudOfSix();
    const std::vector<ParticleId> before = cloud.id;
    orderByLocation(cloud, particleOrderInterval + 1);
    EXPECT_EQ(cloud.id, before);
}

TEST(ParticleOrder, LeavesACloudWithoutLocations) {
    ParticleCloud cloud = cloudOfSix();
    cloud.carrierLocation.clear(); // an analytic carrier keeps none
    const std::vector<ParticleId> before = cloud.id;
    orderByLocation(cloud, 0);
    EXPECT_EQ(cloud.id, before);
}

TEST(ParticleOrder, AnyPermutationMovesEveryArrayAndRefusesAWrongLength) {
    ParticleCloud cloud = cloudOfSix();
    const std::vector<std::uint32_t> order{5, 0, 4, 1, 3, 2};
    reorderParticles(cloud, order);
    const std::vector<ParticleId> ids{8, 10, 13, 11, 12, 9};
    EXPECT_EQ(cloud.id, ids);
    for (std::size_t k = 0; k < cloud.size(); ++k) {
        const double n = static_cast<double>(cloud.id[k]);
        EXPECT_EQ(cloud.position[k], Vec3(n, 0, 0));
        EXPECT_EQ(cloud.temperature[k], 300 + n);
        EXPECT_EQ(cloud.modelState[2 * k + 1], -n);
    }
    std::vector<double> beside{0, 1, 2, 3, 4, 5};
    reorderParticleArray(beside, order);
    EXPECT_EQ(beside, (std::vector<double>{5, 0, 4, 1, 3, 2}));
    const std::vector<std::uint32_t> tooShort{0, 1};
    EXPECT_THROW(reorderParticles(cloud, tooShort), std::logic_error);
}

TEST(ParticleOrder, ContactCellsXSlowestThenThoseOutsideTheDomain) {
    CollisionSettings collisions;
    collisions.model = CollisionModel::softSphere;
    collisions.softSphere.neighbourSkin = 0; // cells of edge 2 R = 0.2 m
    ParticleSettings particles;
    particles.material = {1.6e11, 8e10};
    SoftSphereCollisions soft(collisions, particles, {}, Box{Vec3::Zero(), Vec3::Constant(1)});
    ParticleCloud cloud;
    const Vec3 at[] = {{0.9, 0.1, 0.1}, {0.1, 0.1, 0.9},    {0.1, 0.9, 0.1}, {2, 0, 0},
                       {0.1, 0.1, 0.1}, {0.15, 0.12, 0.11}, {-1, 0, 0},      {0.5, 0.5, 0.5}};
    for (std::uint32_t k = 0; k < 8; ++k) cloud.add(k, at[k], Vec3::Zero(), 0.1);
    // By cell number x·X + y·Y + z: (0,0,0) holds 4 and 5 (as they are), then (0,0,4),
    // (0,4,0), (2,2,2), (4,0,0); 3 and 6 are outside the box.
    EXPECT_EQ(soft.cellOrder(cloud), (std::vector<std::uint32_t>{4, 5, 1, 2, 7, 0, 3, 6}));
}

} // namespace
} // namespace slides
