// ctest-labels: unit foundation
// The cloud ordered by carrier location (core/particle_order.h): every array, and the model
// state of stateWidth entries a particle, moves with its particle to the order of ascending
// (location, id), at step counts that are multiples of particleOrderInterval only.
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

} // namespace
} // namespace slides
