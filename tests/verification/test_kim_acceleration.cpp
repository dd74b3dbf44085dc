// ctest-labels: history physics
// Kim's acceleration factor G (Eq. 3.10–3.11 as printed in the reference, coefficients of
// Eq. 3.15; physics/kim_acceleration.h):
//  - G → 1 at zero relative acceleration, continuously (1 − G ≈ β √MA1);
//  - β at hand-worked points of Eq. 3.11 (c2 at φ_r = 0);
//  - MA1, MA2 of an exponentially decaying slip s0 e^(−t/T) (MA1 = 2R/(sT), MA2 = MA1²);
//  - the kernel with any G keeps Basset's short-time limit: K/K_B → 1 as the lag → 0, the
//    deviation shrinking as lag^(3/(2 c1)); G < 1 only delays the long-lag decay.
#include "slides/physics/kim_acceleration.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slides {
namespace {

TEST(KimAccelerationFactor, IsOneWithoutRelativeAcceleration) {
    EXPECT_EQ(kimAccelerationFactor(0.0, 0.0), 1.0);
    EXPECT_EQ(kimAccelerationFactor(0.0, 3.0), 1.0);
    for (const double ma1 : {1e-6, 1e-8, 1e-10}) {
        const double g = kimAccelerationFactor(ma1, ma1);   // φ_r = 1
        const double first = kimBeta(1.0) * std::sqrt(ma1); // 1 − G = first (1 − first + …)
        EXPECT_NEAR((1 - g) / first, 1.0, 2 * first) << "MA1 " << ma1;
    }
    EXPECT_LT(kimAccelerationFactor(0.5, 0.1), 1.0);
    EXPECT_GT(kimAccelerationFactor(0.5, 0.1), 0.0);
}

TEST(KimAccelerationFactor, BetaAtHandWorkedPoints) {
    // φ_r = 0: c2 = 22. φ_r = 1: 22/(1 + 1/(0.07·2)) = 2.7017544. φ_r = 16 (φ^¼ = 2):
    // 22/(1 + 32/(0.07·18)) = 0.8334335.
    EXPECT_DOUBLE_EQ(kimBeta(0.0), 22.0);
    EXPECT_NEAR(kimBeta(1.0), 2.7017544, 1e-7);
    EXPECT_NEAR(kimBeta(16.0), 0.8334335, 1e-7);
}

TEST(KimAccelerationFactor, OfAnExponentiallyDecayingSlip) {
    // s = s0 e^(−t/T): ds/dt = −s/T, d²s/dt² = s/T²: MA1 = 2R/(sT), MA2 = 4R²/(s²T²) = MA1².
    const double radius = 30e-6, slip = 2.0, decay = 1e-3;
    const double ma1 = kimFirstAcceleration(radius, slip, -slip / decay);
    const double ma2 = kimSecondAcceleration(radius, slip, slip / (decay * decay));
    EXPECT_NEAR(ma1, 2 * radius / (slip * decay), 1e-15);
    EXPECT_NEAR(ma2 / (ma1 * ma1), 1.0, 1e-14);
    EXPECT_NEAR(kimAccelerationFactor(ma1, ma2), 1 / (1 + kimBeta(ma1) * std::sqrt(ma1)), 1e-15);
}

TEST(KimKernel, KeepsBassetsShortTimeLimitForAnyG) {
    // 50 µm in air at 3 m/s slip: crossover lag ~2e-5 s. At lags 1e-8 … 1e-12 s the long-lag term
    // ε = G L/S ∝ lag^(3/(2 c1)) = lag^0.6 is below 0.02, so 1 − K/K_B ≈ c1 ε falls by
    // 100^0.6 ≈ 15.85 per factor 100 in lag (2 % for the ε² term at the largest lag).
    const double radius = 50e-6, viscosity = 1.5e-5, slip = 3.0;
    const double lags[] = {1e-8, 1e-10, 1e-12};
    for (const double g : {1.0, 0.3, 0.02}) {
        double deviations[3];
        for (int k = 0; k < 3; ++k) {
            const double lag = lags[k];
            const double kernel = kimKernel(lag, slip, radius, viscosity, g);
            deviations[k] = 1 - kernel / bassetKernel(lag, radius, viscosity);
            EXPECT_GT(deviations[k], 0.0) << "G " << g << ", lag " << lag;
            if (g < 1) { // G < 1 delays the decay: the kernel lies above G = 1's
                EXPECT_GT(kernel, kimKernel(lag, slip, radius, viscosity, 1.0));
            }
        }
        for (int k = 1; k < 3; ++k)
            EXPECT_NEAR(deviations[k - 1] / deviations[k], std::pow(100.0, 0.6), 0.05 * 15.85)
                << "G " << g << ", lag " << lags[k];
        EXPECT_LT(deviations[2], 1e-3) << "G " << g; // within 0.1 % of Basset at 1e-12 s
    }
}

} // namespace
} // namespace slides
