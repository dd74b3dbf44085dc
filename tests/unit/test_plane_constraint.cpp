// ctest-labels: robustness carrier
// PlaneConstraint (integrate/plane_constraint.h), OpenFOAM's constrainToMeshCentre and
// constrainDirection for a 2-D mesh: positions onto the mid-plane, velocities, eddy
// fluctuations and contact forces into the plane, spins and contact torques onto its normal,
// each array over the entries its model has filled; for an axis normal (x·n exact) and a
// tilted one (to round-off).
#include "slides/integrate/plane_constraint.h"

#include <gtest/gtest.h>

namespace slides {
namespace {

/// Three particles with every model array; the eddies and contacts of the first two only (the
/// third entered this step: its models fill its entries later).
ParticleCloud cloudWithEveryArray() {
    ParticleCloud cloud;
    for (int i = 0; i < 3; ++i) {
        cloud.add(static_cast<ParticleId>(i), Vec3(0.1 * i, 0.2, 0.3 + i), Vec3(1, -2, 3 * i),
                  1e-5);
        cloud.angularVelocity.push_back(Vec3(4, 5, 6 + i));
    }
    for (int i = 0; i < 2; ++i) {
        cloud.eddy.push_back({Vec3(0.5, -0.5, 1.5 + i), 1e-3, 1e-4, 2});
        cloud.contactForce.push_back(Vec3(1e-6, 2e-6, 3e-6));
        cloud.contactTorque.push_back(Vec3(1e-9, 2e-9, 3e-9));
    }
    return cloud;
}

TEST(PlaneConstraint, AxisNormalHoldsEveryArrayExactly) {
    const PlaneConstraint plane(Vec3(0, 0, 2), Box{Vec3(-1, -1, 0), Vec3(1, 1, 2e-3)});
    EXPECT_EQ(plane.normal(), Vec3(0, 0, 1));
    EXPECT_EQ(plane.midPlane(), 1e-3);
    ParticleCloud cloud = cloudWithEveryArray();
    plane.hold(cloud);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        EXPECT_EQ(cloud.position[i], Vec3(0.1 * static_cast<double>(i), 0.2, 1e-3));
        EXPECT_EQ(cloud.velocity[i], Vec3(1, -2, 0));
        EXPECT_EQ(cloud.angularVelocity[i], Vec3(0, 0, 6 + static_cast<double>(i)));
    }
    ASSERT_EQ(cloud.eddy.size(), 2u); // not grown: new particles draw their eddy later
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(cloud.eddy[i].standardised, Vec3(0.5, -0.5, 0));
        EXPECT_EQ(cloud.eddy[i].timeLeft, 1e-3);
        EXPECT_EQ(cloud.contactForce[i], Vec3(1e-6, 2e-6, 0));
        EXPECT_EQ(cloud.contactTorque[i], Vec3(0, 0, 3e-9));
    }
}

TEST(PlaneConstraint, TiltedNormalRemovesTheCrossPlaneParts) {
    const Vec3 normal = Vec3(1, 1, 0).normalized();
    // A box symmetric about the plane x + y = 0.2 (its mid-plane offset 0.1·√2).
    const PlaneConstraint plane(normal, Box{Vec3(-0.4, -0.4, 0), Vec3(0.6, 0.6, 1)});
    EXPECT_NEAR(plane.midPlane(), 0.1 * std::sqrt(2.0), 1e-15);
    ParticleCloud cloud = cloudWithEveryArray();
    const ParticleCloud before = cloud;
    plane.hold(cloud);
    std::vector<Vec3> gas{Vec3(3, -1, 2), Vec3(-7, 7, 1)};
    plane.project(gas);
    for (std::size_t i = 0; i < cloud.size(); ++i) {
        EXPECT_NEAR(cloud.position[i].dot(normal), plane.midPlane(), 1e-15);
        // Moved along the normal only; the velocity keeps its in-plane part.
        EXPECT_NEAR((cloud.position[i] - before.position[i]).cross(normal).norm(), 0, 1e-15);
        EXPECT_NEAR(cloud.velocity[i].dot(normal), 0, 1e-15);
        EXPECT_NEAR((before.velocity[i] - cloud.velocity[i]).cross(normal).norm(), 0, 1e-15);
        EXPECT_NEAR(cloud.angularVelocity[i].cross(normal).norm(), 0, 1e-15);
    }
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_NEAR(cloud.eddy[i].standardised.dot(normal), 0, 1e-15);
        EXPECT_NEAR(cloud.contactForce[i].dot(normal), 0, 1e-21);
        EXPECT_NEAR(cloud.contactTorque[i].cross(normal).norm(), 0, 1e-24);
    }
    EXPECT_NEAR(gas[0].dot(normal), 0, 1e-15);
    EXPECT_NEAR((gas[1] - Vec3(-7, 7, 1)).norm(), 0, 1e-15); // already in the plane
}

} // namespace
} // namespace slides
