// ctest-labels: heat physics history
// Unsteady heat transfer of Michaelides & Feng (Eq. 3.29; 1994, J. Heat Transfer 116:305;
// physics/michaelides_feng.h) for a sphere suddenly placed in fluid at another uniform
// temperature θf (a step change). With θ = θp − θf, Eq. 3.29 per unit particle heat capacity is
//   dθ/dt = −a θ − r_T d/dt ∫_0^t θ(τ)/√(t − τ) dτ,   a = 3K_f/(ρp c_p R²),
//   r_T = 3K_f/(ρp c_p R √(π κ_f)),
// and its Laplace transform Θ(p) = θ0/(p + b√p + a), b = r_T √π. With β1, β2 the roots of
// β² − bβ + a = 0 (√p + β1)(√p + β2) = p + b√p + a, and the inverse transform of 1/(√p + β) is
// 1/√(πt) − β E(β√t), E(z) = e^{z²} erfc(z), so
//   θ(t)/θ0 = [β2 E(β2√t) − β1 E(β1√t)] / (β2 − β1),
// real for real roots (b² > 4a: a light particle in water) and for the complex pair of a metal
// particle in gas (b² < 4a; E of a complex argument from libcerf, support/complex_error.h).
// As ρf c_f/(ρp c_p) → 0, b/√a = √(3 ρf c_f/(ρp c_p)) → 0 and θ tends to
// the quasi-steady Nu = 2 relaxation θ0 e^{−at}: steel in air lies within b/√a of it. The step
// (trapezoid rule with the history implicit, window + exponential tail) converges toward order 2
// (2.00 in air; 1.55 → 1.75 in water, whose history rate is pre-asymptotic at these steps);
// through the real stepper it heats as the step alone does, beside the Maxey–Riley step's memory.
#include "../support/complex_error.h"
#include "../support/gas_scenes.h"
#include "../support/test_scenes.h"
#include "slides/physics/michaelides_feng.h"
#include "slides/run/stepper.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <numbers>
#include <vector>

namespace slides {
namespace {

using Complex = std::complex<double>;

/// A sphere and its fluid: ρp c_p, R; ρf, c_f, K_f.
struct HeatCase {
    const char* name;
    double particleDensity, particleSpecificHeat, radius;
    double fluidDensity, fluidSpecificHeat, conductivity;

    MichaelidesFengRates rates() const {
        return michaelidesFengRates(particleDensity, particleSpecificHeat, radius, fluidDensity,
                                    fluidSpecificHeat, conductivity);
    }
    /// θ(t)/θ0 of the closed form.
    double exact(double time) const {
        const MichaelidesFengRates r = rates();
        const double a = r.conductionRate, b = r.historyRate * std::sqrt(std::numbers::pi);
        const Complex root = std::sqrt(Complex(b * b - 4 * a));
        const Complex beta1 = (b - root) / 2.0, beta2 = (b + root) / 2.0;
        const double s = std::sqrt(time);
        const Complex value = (beta2 * test::scaledComplementaryError(beta2 * s) -
                               beta1 * test::scaledComplementaryError(beta1 * s)) /
                              (beta2 - beta1);
        return value.real();
    }
};

// A 100 µm polymer sphere (ρp c_p = 1e6 J/(m³ K)) in water: b² > 4a.
const HeatCase water{"polymer in water", 1000, 1000, 100e-6, 1000, 4180, 0.6};
// A 50 µm steel sphere in air: b² < 4a, ρf c_f/(ρp c_p) = 3.4e-4.
const HeatCase air{"steel in air", 7800, 460, 50e-6, 1.2, 1005, 0.0257};

/// θ/θ0 after each of 5·stepsPerTau steps of τ_θ/stepsPerTau of the physics step (θf = 0).
std::vector<double> stepTemperatures(const HeatCase& heat, int stepsPerTau, double accuracy) {
    const MichaelidesFengRates rates = heat.rates();
    const double h = 1 / (rates.conductionRate * stepsPerTau);
    const int steps = 5 * stepsPerTau;
    const WindowTailLayout layout = WindowTailLayout::make(h, steps * h, accuracy);
    std::vector<double> state(michaelidesFengDoubles(layout), 0.0);
    std::vector<double> temperatures;
    double temperature = 1.0;
    for (int n = 1; n <= steps; ++n) {
        temperature = advanceMichaelidesFeng(rates, layout, state.data(), temperature, 0.0, h);
        temperatures.push_back(temperature);
    }
    return temperatures;
}

/// Largest |θ/θ0 − exact| over the steps of [0, 5 τ_θ].
double largestError(const HeatCase& heat, int stepsPerTau, double accuracy) {
    const std::vector<double> temperatures = stepTemperatures(heat, stepsPerTau, accuracy);
    const double h = 1 / (heat.rates().conductionRate * stepsPerTau);
    double worst = 0;
    for (std::size_t n = 0; n < temperatures.size(); ++n)
        worst = std::max(worst, std::abs(temperatures[n] - heat.exact(double(n + 1) * h)));
    return worst;
}

TEST(MichaelidesFeng, ClosedFormStartsAtTheStep) {
    // The closed form itself: θ(0) = θ0 (E on the real axis: test_history.cpp).
    EXPECT_NEAR(water.exact(0), 1.0, 1e-12);
    EXPECT_NEAR(air.exact(0), 1.0, 1e-12);
}

TEST(MichaelidesFeng, StepChangeFollowsTheClosedFormConvergingToSecondOrder) {
    // The largest error is on the first steps, where the history's rate b² = π r_T² times the
    // step is not yet small (0.16 at τ_θ/80 in water): the order rises toward 2 as the step
    // shrinks (Basset's start mode takes the √t exactly, physics/history_integrator.h).
    for (const HeatCase& heat : {water, air}) {
        std::vector<double> errors;
        for (int stepsPerTau : {40, 80, 160, 320})
            errors.push_back(largestError(heat, stepsPerTau, 1e-9));
        std::printf("%s: largest |Δθ|/θ0 %.2e, %.2e, %.2e, %.2e at τ_θ/40 … τ_θ/320 (orders %.2f, "
                    "%.2f, %.2f); %.2e at τ_θ/80 with accuracy 1e-3\n",
                    heat.name, errors[0], errors[1], errors[2], errors[3],
                    std::log2(errors[0] / errors[1]), std::log2(errors[1] / errors[2]),
                    std::log2(errors[2] / errors[3]), largestError(heat, 80, 1e-3));
        EXPECT_LT(errors[3], 2e-5) << heat.name;
        EXPECT_GT(std::log2(errors[2] / errors[3]), 1.7) << heat.name;
        EXPECT_LT(largestError(heat, 80, 1e-3), 1.2 * errors[1]) << heat.name; // the tail's share
    }
}

TEST(MichaelidesFeng, HeavyParticleInGasApproachesTheQuasiSteadyRelaxation) {
    // b/√a = √(3 ρf c_f/(ρp c_p)) = 0.032 for steel in air; the history and the fluid's heat
    // capacity move θ from e^{−at} by less than that, and by more than a tenth of it (the history
    // is there: it slows the relaxation at long times, θ ∝ t^{−3/2}).
    const MichaelidesFengRates rates = air.rates();
    const double scale = std::sqrt(3 * rates.fluidCapacityRatio);
    double worst = 0;
    for (double t = 0.05; t <= 5; t += 0.05) {
        const double time = t / rates.conductionRate;
        worst = std::max(worst, std::abs(air.exact(time) - std::exp(-t)));
    }
    std::printf("largest |θ/θ0 − e^{−t/τ_θ}| %.3e against b/√a = %.3e\n", worst, scale);
    EXPECT_LT(worst, scale);
    EXPECT_GT(worst, 0.1 * scale);
}

TEST(MichaelidesFeng, RunHeatsBesideTheMaxeyRileyMemory) {
    // The polymer sphere carried by uniform water-like gas at 300 K, released at 500 K with
    // the gas velocity, alone and with Basset history on (its memory first in the model state):
    // the stepper's temperatures follow the closed form as the physics step does.
    for (const HistoryModel history : {HistoryModel::none, HistoryModel::basset}) {
        Scene scene = test::singleParticleScene();
        scene.fluid = {water.fluidDensity, 1e-6, 300, water.conductivity, water.fluidSpecificHeat};
        scene.particles.radius.value = water.radius;
        scene.particles.density = water.particleDensity;
        scene.particles.specificHeat = water.particleSpecificHeat;
        scene.particles.injectionTemperature = 500;
        scene.physics.heatTransfer = HeatTransferModel::michaelidesFeng;
        scene.physics.history = history;
        scene.physics.historyAccuracy = 1e-9;
        const double tau = 1 / water.rates().conductionRate;
        scene.time.dt = tau / 80;
        scene.time.endTime = 5 * tau;
        const test::UniformTurbulentGas gas(0.0, 0.0, 300, Vec3(0.1, 0, 0));
        Stepper stepper(scene, gas);
        const std::vector<double> alone = stepTemperatures(water, 80, 1e-9);
        double worst = 0, fromStep = 0;
        for (std::size_t n = 0; !stepper.finished(); ++n) {
            stepper.step();
            const double temperature = stepper.cloud().temperature.at(0);
            worst =
                std::max(worst, std::abs(temperature - (300 + 200 * water.exact(stepper.time()))));
            fromStep = std::max(fromStep, std::abs(temperature - (300 + 200 * alone.at(n))));
        }
        std::printf("run (history %s): largest |Δθ| %.2e K of 200 K, %.1e K from the step alone\n",
                    history == HistoryModel::none ? "none" : "basset", worst, fromStep);
        EXPECT_LT(fromStep, 200 * 1e-12); // the same arithmetic, to round-off
        EXPECT_LT(worst, 200 * 1.2e-4);   // the step's own error at τ_θ/80 (above)
    }
}

} // namespace
} // namespace slides
