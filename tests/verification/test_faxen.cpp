// ctest-labels: physics history
// Faxén terms of Eq. 3.2 (Maxey & Riley 1983, Phys. Fluids 26:883; physics/faxen.h) through the
// real stepper. A small heavy sphere under Stokes drag alone, moving along plane Poiseuille flow
// u = U(1 − y²/h²) e_x at a fixed y, settles where the drag on u + (R²/6)∇²u − v vanishes:
//   v = u(y) + (R²/6)∇²u = u(y) − U R²/(3h²),
// a lag of U R²/(3h²) behind the local gas; without the Faxén terms it settles at v = u(y). The
// trapezoid step's fixed point of a constant-coefficient relaxation is exact, and after 100 τ
// the start has decayed far below the 1e-6 relative tolerance, which leaves room for the
// round-off of v (1e-16 of 1 m/s against a lag of 3.3e-5 m/s). The keys reach the scene, and a
// carrier without ∇²U is refused with one error naming physics.faxen.
#include "../support/test_scenes.h"
#include "slides/carrier/plane_poiseuille.h"
#include "slides/config/dictionary.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

namespace slides {
namespace {

constexpr double centrelineVelocity = 1.0; // U [m/s]
constexpr double halfWidth = 1e-3;         // h [m]
constexpr double particleRadius = 1e-5;    // R [m]
constexpr double height = 0.5 * halfWidth; // y of the particle's path [m]

/// The particle's velocity along the flow less the gas's at its height, after 100 response times.
double settledSlip(bool faxen) {
    Scene scene = test::singleParticleScene();
    scene.particles.radius.value = particleRadius;
    scene.physics.drag = DragModel::stokes;
    scene.physics.faxen = faxen;
    scene.nozzle.centre = {0, height, 0};
    const double responseTime = 2 * scene.particles.density * particleRadius * particleRadius /
                                (9 * scene.fluid.density * scene.fluid.kinematicViscosity);
    scene.time.dt = responseTime / 10;
    scene.time.endTime = 100 * responseTime;
    const PlanePoiseuille channel(centrelineVelocity, halfWidth, scene.fluid.temperature);
    Stepper stepper(scene, channel);
    while (!stepper.finished()) stepper.step();
    const ParticleCloud& cloud = stepper.cloud();
    const double y = cloud.position[0].y();
    EXPECT_NEAR(y, height, 1e-12 * halfWidth); // no force across the flow
    const double gas = centrelineVelocity * (1 - y * y / (halfWidth * halfWidth));
    return cloud.velocity[0].x() - gas;
}

TEST(FaxenTerms, HeavySphereLagsPoiseuilleFlowByTheCurvatureTerm) {
    const double lag = centrelineVelocity * particleRadius * particleRadius /
                       (3 * halfWidth * halfWidth); // U R²/(3h²) = 3.33e-5 m/s
    const double withFaxen = settledSlip(true);
    const double without = settledSlip(false);
    std::printf("settled slip %.9e m/s with Faxén (closed form %.9e, relative error %.1e), "
                "%.3e without\n",
                withFaxen, -lag, std::abs(withFaxen / -lag - 1), without);
    EXPECT_NEAR(withFaxen, -lag, 1e-6 * lag);
    EXPECT_NEAR(without, 0.0, 1e-6 * lag);
}

/// A case dictionary with this carrier and physics, read as a Scene.
Scene sceneWith(const std::string& carrier, const std::string& physics) {
    const std::string text = "fluid { density 1.2; kinematicViscosity 1.5e-5; }\n"
                             "nozzle { centre (0 0 0); axis (1 0 0); radius 1e-4; }\n"
                             "carrier { " +
                             carrier + " }\nphysics { " + physics +
                             " }\n"
                             "particles { count 1; density 2500; "
                             "radiusDistribution { type fixed; value 1e-5; } }\n"
                             "injection { mode allAtStart; seed 1; }\n"
                             "time { dt 1e-4; endTime 0.01; }\n"
                             "domain { min (-1 -1 -1); max (1 1 1); }\n"
                             "surfaces { }\n"
                             "output { interval 0.01; }\n";
    return sceneFromDictionary(Dictionary::parseString(text, "slidesProperties"), ".");
}

TEST(FaxenTerms, KeysReachTheSceneAndACarrierWithoutLaplacianIsRefused) {
    const std::string channel =
        "type planePoiseuille; planePoiseuilleCoeffs { centrelineVelocity 2; halfWidth 0.01; }";
    const Scene on = sceneWith(channel, "faxen on;");
    EXPECT_TRUE(on.physics.faxen);
    EXPECT_TRUE(on.physics.unsteadyForces());
    EXPECT_EQ(on.carrier.type, CarrierType::planePoiseuille);
    EXPECT_EQ(on.carrier.centrelineVelocity, 2);
    EXPECT_EQ(on.carrier.channelHalfWidth, 0.01);
    EXPECT_FALSE(sceneWith(channel, "").physics.faxen); // off by default
    try {
        sceneWith("type analyticJet; analyticJetCoeffs { nozzleVelocity 10; }", "faxen on;");
        ADD_FAILURE() << "the Faxén terms were accepted on a carrier without ∇²U";
    } catch (const InputError& error) {
        EXPECT_NE(std::string(error.what()).find("physics.faxen"), std::string::npos)
            << error.what();
    }
}

TEST(FaxenTerms, PoiseuilleCarrierGivesItsClosedForm) {
    const PlanePoiseuille channel(centrelineVelocity, halfWidth, 300);
    const Vec3 x(0.3, height, -0.2);
    CarrierSample sample;
    channel.sample(std::span(&x, 1), 0,
                   {.velocityGradient = true, .temperature = true, .velocityLaplacian = true},
                   sample);
    EXPECT_DOUBLE_EQ(sample.velocity[0].x(), 0.75);
    EXPECT_DOUBLE_EQ(sample.velocityGradient[0](0, 1), -1000.0); // −2Uy/h²
    EXPECT_DOUBLE_EQ(sample.velocityLaplacian[0].x(), -2e6);     // −2U/h²
    EXPECT_EQ(sample.temperature[0], 300);
}

} // namespace
} // namespace slides
