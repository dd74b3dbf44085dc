// ctest-labels: history physics
// The finite-Reynolds kernels' tables (physics/finite_reynolds_kernel.h): q and w of Mei &
// Adrian's kernel (Eq. 3.5) against their closed forms, Kim's (Eq. 3.9) against direct
// quadrature, both against the pointwise kernels of Eq. 3.5 and 3.9, and the spectrum κ against
// the kernel it must rebuild.
#include "slides/physics/finite_reynolds_kernel.h"
#include "slides/physics/history_kernel.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace slides {
namespace {

/// Mei & Adrian's q and w in closed form: with z = y^(1/4), F = (1 + z³)^(−2),
///   q = ∫_0^z 4ζ(1 + ζ³)^(−2) dζ = (4/3)[z²/(1 + z³) + J(z)],
///   J = ∫_0^z ζ/(1 + ζ³) = −ln(1 + z)/3 + ln(z² − z + 1)/6 + [atan((2z − 1)/√3) + π/6]/√3,
///   w = y q − ∫_0^z 4ζ⁵(1 + ζ³)^(−2) dζ = y q − (4/3)[ln(1 + z³) − z³/(1 + z³)];
/// below z = ½ by their series, which converge there to round-off in 40 terms.
double meiAdrianQ(double y) {
    const double z = std::pow(y, 0.25);
    if (z < 0.5) {
        double sum = 0;
        for (int k = 0; k < 40; ++k)
            sum += (k % 2 ? -1 : 1) * (k + 1) * std::pow(z, 3 * k + 2) / (3 * k + 2);
        return 4 * sum;
    }
    const double j =
        -std::log1p(z) / 3 + std::log(z * z - z + 1) / 6 +
        (std::atan((2 * z - 1) / std::sqrt(3.0)) + std::numbers::pi / 6) / std::sqrt(3.0);
    return (4.0 / 3.0) * (z * z / (1 + z * z * z) + j);
}
double meiAdrianW(double y) {
    const double z = std::pow(y, 0.25), z3 = z * z * z;
    if (z < 0.5) {
        double sum = 0;
        for (int k = 0; k < 40; ++k)
            sum += (k % 2 ? -1 : 1) * (k + 1) * std::pow(z, 3 * k + 6) * 4.0 /
                   ((3 * k + 2) * (3 * k + 6));
        return 4 * sum;
    }
    return y * meiAdrianQ(y) - (4.0 / 3.0) * (std::log1p(z3) - z3 / (1 + z3));
}

TEST(FiniteReynoldsKernel, MeiAdrianTablesMatchTheClosedForms) {
    // Quintic Hermite on δ = 0.05 in ln y errs ~δ⁶/46080 of the sixth derivative: ~1e-13.
    const auto& kernel = FiniteReynoldsKernel::of(meiAdrianShape);
    double worstQ = 0, worstW = 0;
    for (double logY = -50; logY <= 50; logY += 0.0137) {
        const double y = std::exp(logY);
        worstQ = std::max(worstQ, std::abs(kernel.q(y) / meiAdrianQ(y) - 1));
        worstW = std::max(worstW, std::abs(kernel.w(y) / meiAdrianW(y) - 1));
    }
    std::printf("Mei–Adrian tables: q %.2e, w %.2e relative\n", worstQ, worstW);
    EXPECT_LT(worstQ, 1e-11);
    EXPECT_LT(worstW, 1e-11);
}

TEST(FiniteReynoldsKernel, KimTablesMatchDirectQuadrature) {
    // q(y) = ∫_0^y u^(−½)(1 + u^0.6)^(−2.5) du and w = y q − ∫_0^y u^(½)F du, in u = ζ^10
    // (smooth integrands 10ζ⁴F, 10ζ^14 F), by 2000 Simpson panels: error below 1e-13.
    const auto& kernel = FiniteReynoldsKernel::of(kimShape);
    const auto shape = [](double zeta) { return std::pow(1 + std::pow(zeta, 6), -2.5); };
    double worstQ = 0, worstW = 0;
    for (double logY = -20; logY <= 20; logY += 1.37) {
        const double y = std::exp(logY), top = std::pow(y, 0.1);
        const int panels = 2000;
        double q = 0, r = 0;
        for (int i = 0; i <= 2 * panels; ++i) {
            const double zeta = top * i / (2.0 * panels);
            const double weight = (i == 0 || i == 2 * panels) ? 1 : (i % 2 ? 4 : 2);
            q += weight * 10 * std::pow(zeta, 4) * shape(zeta);
            r += weight * 10 * std::pow(zeta, 14) * shape(zeta);
        }
        q *= top / (6.0 * panels);
        r *= top / (6.0 * panels);
        worstQ = std::max(worstQ, std::abs(kernel.q(y) / q - 1));
        worstW = std::max(worstW, std::abs(kernel.w(y) / (y * q - r) - 1));
    }
    std::printf("Kim tables: q %.2e, w %.2e relative\n", worstQ, worstW);
    EXPECT_LT(worstQ, 1e-11);
    EXPECT_LT(worstW, 1e-10);
}

TEST(FiniteReynoldsKernel, CrossoverLagReproducesTheKernelsOfEq35And39) {
    // K̂ R/√(πν) with ℓ_c of physics/finite_reynolds_kernel.h is Eq. 3.5's and Eq. 3.9's kernel.
    const double radius = 20e-6, viscosity = 1.5e-5,
                 basset = radius / std::sqrt(std::numbers::pi * viscosity);
    for (const double slip : {0.01, 1.0, 100.0}) {
        for (const double lag : {1e-9, 1e-6, 1e-3}) {
            const double meiAdrian =
                FiniteReynoldsKernel::of(meiAdrianShape)
                    .kernel(lag, crossoverLag(meiAdrianShape, slip, radius, viscosity));
            EXPECT_NEAR(meiAdrian * basset / meiAdrianKernel(lag, slip, radius, viscosity), 1,
                        1e-12);
            const double g = 0.6;
            const double kim = FiniteReynoldsKernel::of(kimShape).kernel(
                lag, crossoverLag(kimShape, slip, radius, viscosity, g));
            EXPECT_NEAR(kim * basset / kimKernel(lag, slip, radius, viscosity, g), 1, 1e-12);
            // Kim's initial-slip kernel K1 (Eq. 3.13): G1 of Eq. 3.14 in ℓ_c.
            const double densityRatio = 2000, reynolds = 2 * radius * slip / viscosity;
            const double initial = FiniteReynoldsKernel::of(kimShape).kernel(
                lag, crossoverLag(kimShape, slip, radius, viscosity,
                                  kimInitialFactor(reynolds, densityRatio)));
            EXPECT_NEAR(initial * basset /
                            kimInitialKernel(lag, slip, radius, viscosity, densityRatio),
                        1, 1e-12);
        }
    }
}

TEST(FiniteReynoldsKernel, SpectrumRebuildsTheKernel) {
    // K̂(ℓ) = π^(−½) ∫ e^{−xℓ} x^(−½) κ(x ℓ_c) dx, by the trapezoid rule in ln x (step 0.05:
    // its aliasing error e^{−π²/0.05} is nil); the table's cubic interpolation errs ~1e-8.
    for (const auto& shape : {meiAdrianShape, kimShape}) {
        const auto& kernel = FiniteReynoldsKernel::of(shape);
        const double crossover = 1.0;
        double worst = 0;
        for (const double lag : {1e-4, 1e-2, 0.3, 1.0, 3.0, 1e2, 1e4}) {
            double sum = 0;
            for (double y = -60; y <= 30; y += 0.05) {
                const double x = std::exp(y);
                sum +=
                    0.05 * std::exp(-x * lag) * std::sqrt(x) * kernel.spectrumRatio(x * crossover);
            }
            sum /= std::sqrt(std::numbers::pi);
            const double error = std::abs(sum / kernel.kernel(lag, crossover) - 1);
            EXPECT_LT(error, 1e-6) << "lag " << lag;
            worst = std::max(worst, error);
        }
        std::printf("c1 = %.1f: spectrum rebuilds the kernel to %.2e\n", shape.exponent, worst);
    }
}

TEST(FiniteReynoldsKernel, IntervalWeightIsContinuousWhereItsQuadratureChanges) {
    // (W(ℓ + h) − W(ℓ))/h below ℓ = 32 h, Gauss–Legendre of Q above: both the mean of Q.
    const auto& kernel = FiniteReynoldsKernel::of(meiAdrianShape);
    for (const double crossover : {1e-3, 1.0, 1e3}) {
        const double h = 1e-2, lag = 32 * h;
        const double below =
            (kernel.secondIntegral(lag + h, crossover) - kernel.secondIntegral(lag, crossover)) / h;
        EXPECT_NEAR(kernel.intervalWeight(lag, h, crossover) / below, 1, 1e-12);
    }
}

} // namespace
} // namespace slides
