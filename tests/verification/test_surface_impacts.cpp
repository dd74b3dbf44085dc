// ctest-labels: deposition collision
// Meeting surfaces and the deposit (surfaces/surface_impacts.h) on paths made by hand, for
// Table 5.2's particle (R = 80 µm) at a plane at x = 2 mm facing −x:
//  - a chord that reaches the plane within the step is met even when a collision within the
//    step turned both its end velocities away (the mean velocity of the chord meets it): a
//    rebound with e then leaves the sphere e (1 − s) h |c_n| in front of the plane, as the
//    impulse law flown for the rest of the step gives;
//  - a sphere that started against a deposited particle and is set back along their line of
//    centres, which points into the plane, rests on the plane (centre R in front of it), not
//    sunk into it.
#include "../support/test_scenes.h"
#include "slides/surfaces/surface_impacts.h"

#include <gtest/gtest.h>

namespace slides {
namespace {

constexpr double radius = 80e-6, plateX = 2e-3, step = 1e-5;

Scene plateScene(SurfaceInteraction interaction) {
    Scene scene = test::singleParticleScene();
    scene.particles.density = 5680;
    scene.particles.radius.value = radius;
    scene.particles.material = {167e9, 77e9, 200e6, 0.046};
    scene.deposition.factor = 5000;
    scene.collisions.restitution = {RestitutionModel::constant, 0.5, 3};
    scene.surfaces.push_back(
        {"plate", Vec3(plateX, 0, 0), Vec3(-1, 0, 0), {160e9, 80e9, 0, 1.1}, interaction, "", {}});
    return scene;
}

/// One particle at end with velocity v, having flown from start over one step.
ParticleCloud oneParticle(const Vec3& end, const Vec3& v) {
    ParticleCloud cloud;
    cloud.add(1, end, v, radius);
    cloud.angularVelocity.push_back(Vec3::Zero());
    return cloud;
}

TEST(SurfaceImpacts, ChordReachingThePlaneIsMetThoughBothVelocitiesLeaveIt) {
    const Scene scene = plateScene(SurfaceInteraction::rebound);
    const test::UniformFlow gas(Vec3::Zero());
    SurfaceImpacts impacts(scene.surfaces, scene.collisions, scene.deposition, scene.particles,
                           scene.physics.heatTransfer, gas);
    // Gap +10 µm at the start, −10 µm at the end (the chord at 2 m/s towards the plate, the
    // velocities −1 m/s, away from it): touch at s = ½ with c_n = 2 m/s.
    const Vec3 start(plateX - radius - 10e-6, 0, 0), end(plateX - radius + 10e-6, 0, 0);
    ParticleCloud cloud = oneParticle(end, Vec3(-1, 0, 0));
    Arrival arrival;
    const ImpactResult result =
        impacts.meet(cloud, 0, start, Vec3(-1, 0, 0), step, step, std::nullopt, arrival);
    EXPECT_EQ(result, ImpactResult::rebounded);
    EXPECT_EQ(impacts.rebounds()[0], 1u);
    const double gap = plateX - cloud.position[0].x() - radius;
    EXPECT_NEAR(gap, 0.5 * 0.5 * step * 2, 1e-15);                 // e (1 − s) h c_n
    EXPECT_NEAR(cloud.velocity[0].x(), -1 - (1 + 0.5) * 2, 1e-12); // v + (c' − c)
}

TEST(SurfaceImpacts, SphereSetBackFromTheDepositRestsOnThePlane) {
    const Scene scene = plateScene(SurfaceInteraction::deposit);
    const test::UniformFlow gas(Vec3::Zero());
    SurfaceImpacts impacts(scene.surfaces, scene.collisions, scene.deposition, scene.particles,
                           scene.physics.heatTransfer, gas);
    // A deposited particle 150 µm from the plate; the new one starts 85 µm from it, 60 µm
    // aside, overlapping it (centres 88.5 µm apart), and moves towards it along the plate at
    // 0.3 m/s (0.2 m/s along the line of centres, below the deposit's 0.847 m/s): it sticks.
    // Set back to 160 µm along the line of centres it would sit 32 µm from the plate.
    Arrival deposited;
    deposited.position = Vec3(plateX - 150e-6, 0, 0);
    deposited.radius = radius;
    impacts.addToDeposit(deposited);
    impacts.indexDeposit();
    const Vec3 start(plateX - 85e-6, 60e-6, 0);
    const Vec3 velocity(0, -0.3, 0);
    ParticleCloud cloud = oneParticle(start + step * velocity, velocity);
    Arrival arrival;
    const ImpactResult result =
        impacts.meet(cloud, 0, start, velocity, step, step, std::nullopt, arrival);
    ASSERT_EQ(result, ImpactResult::arrived);
    EXPECT_EQ(impacts.deposit().size(), 2u);
    EXPECT_NEAR(plateX - arrival.position.x(), radius, 1e-15);
}

} // namespace
} // namespace slides
