// ctest-labels: physics history
// Faxén terms of Eq. 3.2 (Maxey & Riley 1983, Phys. Fluids 26:883; physics/faxen.h) through the
// real stepper. A small heavy sphere under Stokes drag alone, moving along plane Poiseuille flow
// u = U(1 − y²/h²) e_x at a fixed y, settles where the drag on u + (R²/6)∇²u − v vanishes:
//   v = u(y) + (R²/6)∇²u = u(y) − U R²/(3h²),
// a lag of U R²/(3h²) behind the local gas; without the Faxén terms it settles at v = u(y). The
// trapezoid step's fixed point of a constant-coefficient relaxation is exact, and after 100 τ
// the start has decayed far below the 1e-6 relative tolerance, which leaves room for the
// round-off of v (1e-16 of 1 m/s against a lag of 3.3e-5 m/s). The added mass's Faxén term
// d/dt((R²/10)∇²u) needs a ∇²u that changes along the path: a neutrally buoyant 5 mm sphere with
// added mass in the decaying Taylor–Green vortex (∇²u = −2k²u, k²R² = 0.1) follows the
// Maxey–Riley equation with both Faxén terms, integrated in the test by RK4 with steps 100 times
// shorter: the step's error falls at order 2 and is below 1 % of what the R²/10 term changes. The
// keys reach the scene, and a carrier without ∇²U is refused with one error naming physics.faxen.
#include "../support/test_scenes.h"
#include "slides/carrier/plane_poiseuille.h"
#include "slides/carrier/taylor_green_vortex.h"
#include "slides/config/dictionary.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

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

/// Particle velocity and position.
struct Motion {
    Vec3 position, velocity;
};

/// dv/dt of Maxey & Riley's equation with Stokes drag and added mass (C_A = ½, no pressure
/// gradient, no gravity) and the Faxén terms in the Taylor–Green vortex, where ∇²u = −2k²u:
///   (ρp + ρf/2) dv/dt = ρp/τ_p (u + (R²/6)∇²u − v) + (ρf/2) [Du/Dt + (R²/10) d/dt ∇²u],
/// d/dt along the path: d/dt ∇²u = −2k² (∂u/∂t + ∇u v). addedMassFaxen 0 drops the R²/10 term.
Vec3 acceleration(const TaylorGreenVortex& vortex, const Motion& motion, double time,
                  double wavenumber, double radius, double responseTime, double addedMassFaxen) {
    CarrierSample gas;
    vortex.sample(std::span(&motion.position, 1), time,
                  {.velocityGradient = true, .timeDerivative = true}, gas);
    const Vec3& u = gas.velocity[0];
    const Mat3& gradient = gas.velocityGradient[0];
    const Vec3& dudt = gas.velocityTimeDerivative[0];
    const double curvature = wavenumber * wavenumber * radius * radius; // k²R²
    const double effective = 1.5; // (ρp + ρf/2)/ρp for ρp = ρf
    const Vec3 drag = (u * (1 - curvature / 3) - motion.velocity) / responseTime;
    const Vec3 fluid = 0.5 * (dudt + gradient * u -
                              addedMassFaxen * curvature / 5 * (dudt + gradient * motion.velocity));
    return (drag + fluid) / effective;
}

TEST(FaxenTerms, AddedMassTermFollowsTheEquationInTheTaylorGreenVortex) {
    Scene scene = test::singleParticleScene();
    scene.particles.density = scene.fluid.density;
    scene.particles.radius.value = 5e-3;
    scene.physics.drag = DragModel::stokes;
    scene.physics.addedMass = true;
    scene.physics.faxen = true;
    const double wavelength = 0.1, radius = 5e-3;
    const double wavenumber = 2 * std::numbers::pi / wavelength;
    scene.nozzle.centre = {wavelength / 8, wavelength / 5, 0};
    scene.time.endTime = 0.3;
    const double responseTime = 2 * radius * radius / (9 * scene.fluid.kinematicViscosity);
    const TaylorGreenVortex vortex(1.0, wavelength, scene.fluid.kinematicViscosity, 293);

    // The reference: RK4 at 5 µs (a hundredth of the finer step) from the release with the gas
    // velocity; velocities every 5 µs.
    constexpr double referenceStep = 5e-6;
    constexpr int referenceSteps = 60000;
    const auto reference = [&](double addedMassFaxen) {
        CarrierSample gas;
        vortex.sample(std::span(&scene.nozzle.centre, 1), 0, {}, gas);
        Motion motion{scene.nozzle.centre, gas.velocity[0]};
        const double h = referenceStep;
        const auto rate = [&](const Motion& m, double time) {
            return Motion{m.velocity, acceleration(vortex, m, time, wavenumber, radius,
                                                   responseTime, addedMassFaxen)};
        };
        const auto along = [](const Motion& m, const Motion& d, double step) {
            return Motion{m.position + step * d.position, m.velocity + step * d.velocity};
        };
        std::vector<Vec3> velocities{motion.velocity};
        for (int n = 0; n < referenceSteps; ++n) {
            const double t = n * h;
            const Motion k1 = rate(motion, t);
            const Motion k2 = rate(along(motion, k1, h / 2), t + h / 2);
            const Motion k3 = rate(along(motion, k2, h / 2), t + h / 2);
            const Motion k4 = rate(along(motion, k3, h), t + h);
            motion = along(motion, k1, h / 6);
            motion = along(motion, k2, h / 3);
            motion = along(motion, k3, h / 3);
            motion = along(motion, k4, h / 6);
            velocities.push_back(motion.velocity);
        }
        return velocities;
    };
    const std::vector<Vec3> withTerm = reference(1), withoutTerm = reference(0);
    double termEffect = 0;
    for (std::size_t n = 0; n < withTerm.size(); ++n)
        termEffect = std::max(termEffect, (withTerm[n] - withoutTerm[n]).norm());
    const auto largestError = [&](double dt) {
        scene.time.dt = dt;
        Stepper stepper(scene, vortex);
        double error = 0;
        const auto stride = static_cast<std::size_t>(std::lround(dt / referenceStep));
        for (std::size_t n = 1; !stepper.finished(); ++n) {
            stepper.step();
            error = std::max(error, (stepper.cloud().velocity[0] - withTerm.at(n * stride)).norm());
        }
        return error;
    };
    const double coarse = largestError(1e-3), fine = largestError(5e-4);
    std::printf("largest |v − v_RK4| %.2e m/s at dt 1 ms, %.2e at 0.5 ms (order %.2f); the R²/10 "
                "term changes v by %.2e m/s\n",
                coarse, fine, std::log2(coarse / fine), termEffect);
    EXPECT_GT(std::log2(coarse / fine), 1.8); // the step's order 2
    EXPECT_LT(fine, 0.01 * termEffect);
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
        "type planePoiseuille; planePoiseuilleCoeffs { centrelineVelocity 2; halfWidth 0.5; }";
    const Scene on = sceneWith(channel, "faxen on;");
    EXPECT_TRUE(on.physics.faxen);
    EXPECT_TRUE(on.physics.unsteadyForces());
    EXPECT_EQ(on.carrier.type, CarrierType::planePoiseuille);
    EXPECT_EQ(on.carrier.centrelineVelocity, 2);
    EXPECT_EQ(on.carrier.channelHalfWidth, 0.5);
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
