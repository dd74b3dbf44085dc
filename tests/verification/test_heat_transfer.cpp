// ctest-labels: heat physics
// Convective heating (Section 3.8, Eq. 3.25–3.28; physics/heat_transfer.h):
//  - Nusselt correlations: Ranz & Marshall (1952) Eq. 3.27 at tabulated (Re, Pr); Acrivos &
//    Taylor (1962) Eq. 3.28 against its series at small Pe and its classical first-order
//    result Nu = 2 (1 + Pe/4); every correlation → 2 (conduction into still gas) as Re → 0;
//  - the thermal response time against m c_p / (h A), h = Nu K_f / d, A = 4πR²;
//  - lumped heating of a particle moving with uniform gas through the real stepper against the
//    exact solution θ(t) = θf + (θ0 − θf) e^(−t/τ_θ), for steps of 0.1 and 5 τ_θ.
#include "../support/gas_scenes.h"
#include "../support/test_scenes.h"
#include "slides/physics/heat_transfer.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace slides {
namespace {

TEST(NusseltNumber, RanzMarshallAtTabulatedPoints) {
    // Nu = 2 + 0.6 Re^(1/2) Pr^(1/3), values worked by hand (Pr^(1/3) of air 0.71 = 0.892112).
    const double prandtl = 0.71;
    EXPECT_NEAR(nusseltNumber(HeatTransferModel::ranzMarshall, 0.0, prandtl), 2.0, 1e-15);
    EXPECT_NEAR(nusseltNumber(HeatTransferModel::ranzMarshall, 1.0, prandtl), 2.535267, 1e-6);
    EXPECT_NEAR(nusseltNumber(HeatTransferModel::ranzMarshall, 100.0, prandtl), 7.352673, 1e-6);
    // Water, Pr = 7: 2 + 0.6·√50·7^(1/3) = 2 + 0.6·7.071068·1.912931 = 10.115880.
    EXPECT_NEAR(nusseltNumber(HeatTransferModel::ranzMarshall, 50.0, 7.0), 10.115880, 1e-6);
}

TEST(NusseltNumber, AcrivosTaylorSeriesAndItsStokesLimit) {
    // Pe = Re·Pr = 0.1: 2 + 0.05 + 0.0025 ln 0.1 + 0.0003404 + 0.0000625 ln 0.1 = 2.0444400.
    EXPECT_NEAR(nusseltNumber(HeatTransferModel::acrivosTaylor, 0.1 / 0.7, 0.7), 2.0444400, 1e-7);
    // First order: (Nu − 2)/Pe → 1/2 (Nu = 2 (1 + Pe/4)); the Pe ln Pe term decides the rest.
    for (double peclet : {1e-3, 1e-4, 1e-5}) {
        const double slope =
            (nusseltNumber(HeatTransferModel::acrivosTaylor, peclet, 1.0) - 2.0) / peclet;
        EXPECT_NEAR(slope, 0.5, 0.3 * peclet * std::abs(std::log(peclet))) << "Pe " << peclet;
    }
}

TEST(NusseltNumber, EveryCorrelationIsConductionInStillGas) {
    for (const auto& entry : heatTransferModelNames()) {
        EXPECT_DOUBLE_EQ(nusseltNumber(entry.value, 0.0, 0.7), 2.0) << entry.name;
        EXPECT_NEAR(nusseltNumber(entry.value, 1e-10, 0.7), 2.0, 1e-4) << entry.name;
        EXPECT_GT(nusseltNumber(entry.value, 0.5, 0.7), 2.0 - 1e-15) << entry.name;
    }
}

TEST(ThermalResponse, IsMassTimesHeatCapacityOverConductance) {
    const double density = 5680, specificHeat = 460, radius = 40e-6, nusselt = 3.7,
                 conductivity = 0.0257;
    const double mass = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * density;
    const double coefficient = nusselt * conductivity / (2 * radius); // h = Nu K / d
    const double area = 4 * std::numbers::pi * radius * radius;
    EXPECT_NEAR(thermalResponseTime(density, specificHeat, radius, nusselt, conductivity) /
                    (mass * specificHeat / (coefficient * area)),
                1.0, 1e-14);
}

class LumpedHeating : public ::testing::TestWithParam<double> {};

/// A 40 µm particle injected at 500 K with the velocity of uniform 300 K gas: no slip, so
/// Re = 0, Nu = 2 and τ_θ = 2 ρp c_p R²/(3·2·K_f) is constant.
Scene heatedParticleScene() {
    Scene scene = test::singleParticleScene();
    scene.particles.radius.value = 40e-6;
    scene.particles.density = 5680;
    scene.particles.specificHeat = 460;
    scene.particles.injectionTemperature = 500;
    scene.fluid.thermalConductivity = 0.0257;
    scene.fluid.specificHeat = 1005;
    scene.physics.heatTransfer = HeatTransferModel::ranzMarshall;
    return scene;
}

double conductionResponseTime(const Scene& scene) { // Nu = 2
    return thermalResponseTime(scene.particles.density, scene.particles.specificHeat,
                               scene.particles.radius.value, 2.0, scene.fluid.thermalConductivity);
}

TEST_P(LumpedHeating, FollowsTheExactExponentialForAnyStep) {
    // Under the drag schemes, and under the Maxey–Riley step (added mass on), which heats on
    // the same carrier sample.
    for (const bool unsteady : {false, true}) {
        Scene scene = heatedParticleScene();
        scene.physics.addedMass = unsteady;
        const double gasTemperature = 300;
        const double tau = conductionResponseTime(scene);
        scene.time.dt = GetParam() * tau;
        scene.time.endTime = 20 * tau;
        const test::UniformTurbulentGas gas(0.0, 0.0, gasTemperature, Vec3(3, 0, 0));
        Stepper stepper(scene, gas);
        while (!stepper.finished()) {
            stepper.step();
            const double exact =
                gasTemperature + (500 - gasTemperature) * std::exp(-stepper.time() / tau);
            // Exact up to round-off of the time sum and exp: 1e-12 relative to the 200 K span.
            ASSERT_NEAR(stepper.cloud().temperature.at(0), exact, 200 * 1e-12)
                << "t = " << stepper.time() / tau << " τ_θ" << (unsteady ? ", added mass" : "");
        }
    }
}

TEST_P(LumpedHeating, ArrivalTakesTheTemperatureAtTheTouch) {
    // The same particle carried at 3 m/s onto a sink 10 mm downstream: it touches at
    // t_a = (0.01 − R)/3, inside a step, and arrives with θ(t_a) of the exponential, not with
    // the temperature at the step's end (which made arrival temperatures first order in dt).
    Scene scene = heatedParticleScene();
    const double tau = conductionResponseTime(scene);
    scene.surfaces.push_back(
        {"sink", Vec3(0.01, 0, 0), Vec3(-1, 0, 0), {}, SurfaceInteraction::absorb, "", {}});
    const double arrivalTime = (0.01 - 40e-6) / 3;
    scene.time.dt = 1.37 * GetParam() * arrivalTime; // the touch falls inside a step
    scene.time.endTime = 20 * arrivalTime;
    const test::UniformTurbulentGas gas(0.0, 0.0, 300, Vec3(3, 0, 0));
    Stepper stepper(scene, gas);
    while (!stepper.finished()) stepper.step();
    ASSERT_EQ(stepper.arrivals().size(), 1u);
    const Arrival& arrival = stepper.arrivals()[0];
    EXPECT_NEAR(arrival.time, arrivalTime, 1e-15);
    EXPECT_NEAR(arrival.temperature, 300 + 200 * std::exp(-arrivalTime / tau), 200 * 1e-12)
        << "τ_θ = " << tau << " s";
}

INSTANTIATE_TEST_SUITE_P(StepsOfATenthAndFiveResponseTimes, LumpedHeating,
                         ::testing::Values(0.1, 5.0));

} // namespace
} // namespace slides
