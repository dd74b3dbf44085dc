// ctest-labels: history physics
// Basset history force (Eq. 3.3 with Stokes drag, added mass and buoyancy) against the closed
// form of a light (ρp/ρf = 0.4, real roots) or heavy (2.5, complex roots) sphere released in a
// uniform stream or settling under gravity (Mordant & Pinton 2000,
// Eur. Phys. J. B 18:343; Daitche 2013, J. Comput. Phys. 254:93, Sec. 5): observed orders of
// the reference quadratures (orders 1 and 2) and of the window + exponential tail, with and
// without initial slip, and the tail's accuracy over 10⁵ steps.
#include "../support/complex_error.h"
#include "slides/physics/history_integrator.h"
#include "slides/physics/history_kernel.h"
#include "slides/physics/unsteady.h"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

namespace slides {
namespace {

/// A sphere in water: light (ρp/ρf = 0.4, the roots below are real) or heavy (glass, 2.5,
/// complex roots: the solution oscillates about its decay).
struct Case {
    double fluidDensity = 1000, particleDensity = 400, viscosity = 1e-6, radius = 1e-3;
    double dragRate() const { // 1/τ_e: Stokes drag per effective mass m_p + m_f/2
        return 1.0 / effectiveResponseTime(particleDensity, fluidDensity, viscosity, radius, 0.5);
    }
    double historyRate() const {
        return bassetHistoryRate(particleDensity, fluidDensity, viscosity, radius, 0.5);
    }
    double gravity() const { // buoyancy-corrected gravity per effective mass along z
        return -9.81 * (particleDensity - fluidDensity) / (particleDensity + 0.5 * fluidDensity);
    }
};
const Case light{};
const Case heavy{1000, 2500, 1e-6, 5e-4};

/// Relative velocity w = v − U of dw/dt = −w/τ − r_H d/dt ∫ w/√(t−τ) dτ + g, w(0) = w0: in
/// Laplace space W (s + r_H√π √s + 1/τ) = w0 + g/s; with λ1,2 the roots of λ² − αλ + 1/τ,
/// α = r_H√π (real or a complex pair, Re λ = α/2 > 0), and E_i = e^{λ_i² t} erfc(λ_i √t):
///   w = [w0 (λ2 E2 − λ1 E1) + g ((1 − E1)/λ1 − (1 − E2)/λ2)] / (λ2 − λ1).
double exactRelativeVelocity(const Case& c, double w0, double g, double t) {
    using Complex = std::complex<double>;
    const double alpha = std::sqrt(std::numbers::pi) * c.historyRate();
    const Complex root = std::sqrt(Complex(alpha * alpha - 4 * c.dragRate()));
    const Complex l1 = 0.5 * (alpha - root), l2 = 0.5 * (alpha + root);
    const Complex e1 = test::scaledComplementaryError(l1 * std::sqrt(t));
    const Complex e2 = test::scaledComplementaryError(l2 * std::sqrt(t));
    return ((w0 * (l2 * e2 - l1 * e1) + g * ((1.0 - e1) / l1 - (1.0 - e2) / l2)) / (l2 - l1))
        .real();
}

TEST(HistoryClosedForm, ComplexErrorFunctionAgreesWithTheRealOne) {
    // The library's real e^{x²}erfc(x) (physics/history_integrator.h) against libcerf's complex
    // one, which the closed forms take, on the real axis.
    for (const double x : {0.0, 0.3, 1.0, 2.4, 2.6, 5.0, 30.0})
        EXPECT_NEAR(test::scaledComplementaryError(std::complex<double>(x)).real() /
                        slides::scaledComplementaryError(x),
                    1.0, 1e-11)
            << "x = " << x;
}

TEST(HistoryClosedForm, StartModeMatchesItsSeriesInExtendedPrecision) {
    // φ = g_0, ∫φ = t g_2, ∫φ/√(t − τ) = √(π t) g_1 at x = α√t (α = 1), g_m(x) = Σ_{k≥m}
    // (−x)^(k−m)/Γ(1 + k/2), summed here in long double (64-bit mantissa) to 60 terms; the
    // power-series branch (x < 0.5) and the erfc one above it. Each is a few roundings of a
    // sum of terms of alternating sign no larger than its first: 4 ulp of double.
    const auto remainder = [](int m, long double x) {
        long double sum = 0, power = 1;
        for (int k = m; k < m + 60; ++k) {
            sum += power / std::tgamma(1.0L + 0.5L * k);
            power *= -x;
        }
        return sum;
    };
    // Small x too, where the series takes fewer terms.
    std::vector<double> arguments{1e-6, 1e-4, 1e-3, 0.01};
    for (double x = 0; x < 0.75; x += 1.0 / 64) arguments.push_back(x);
    for (const double x : arguments) {
        const StartMode mode = startMode(1.0, x * x);
        const double tolerance = 4 * std::numeric_limits<double>::epsilon();
        EXPECT_NEAR(mode.value / static_cast<double>(remainder(0, x)), 1.0, tolerance) << x;
        if (x == 0) continue;
        EXPECT_NEAR(mode.integral / (x * x) / static_cast<double>(remainder(2, x)), 1.0, tolerance)
            << x;
        EXPECT_NEAR(mode.history / (std::sqrt(std::numbers::pi) * x) /
                        static_cast<double>(remainder(1, x)),
                    1.0, tolerance)
            << x;
    }
}

enum class Scheme { reference1, reference2, reference2NaiveStart, windowTail };

std::string nameOf(Scheme scheme) {
    switch (scheme) {
    case Scheme::reference1: return "reference order 1";
    case Scheme::reference2: return "reference order 2";
    case Scheme::reference2NaiveStart: return "reference order 2, naive start";
    case Scheme::windowTail: return "window + tail";
    }
    return "";
}

/// Max |v − v_exact| over the nodes of a run of `steps` steps of h (the first one firstStep h,
/// as for a particle released inside a step), gas U = (1, 0, 0), particle released with
/// v0 = U − s0 along x, gravity along z.
double maxError(Scheme scheme, const Case& c, double s0, double g, double h, long steps,
                double accuracy = 1e-10, double firstStep = 1) {
    const Vec3 gas(1, 0, 0);
    Vec3 v = gas - Vec3(s0, 0, 0);
    HistoryStart start;
    const bool naive = scheme == Scheme::reference2NaiveStart;
    if (!naive) start.startSlip = gas - v;
    SlipStep step;
    step.h = firstStep * h;
    step.implicitness = scheme == Scheme::reference1 ? 1.0 : 0.5;
    step.dragRate = c.dragRate();
    step.historyRate = c.historyRate();
    step.gasStart = step.gasEnd = gas;
    step.forceStart = step.forceEnd = Vec3(0, 0, g);
    const WindowTailLayout layout = WindowTailLayout::make(h, h * steps, accuracy);
    std::vector<double> tailState(layout.doubles(), 0.0);
    WindowTailHistory windowTail(layout, tailState.data());
    FullHistory full(h, scheme == Scheme::reference1 ? 1 : 2, naive ? Vec3(gas - v) : Vec3::Zero());
    double error = 0, t = 0;
    for (long n = 1; n <= steps; ++n) {
        v = (scheme == Scheme::windowTail ? advanceWithHistory(step, v, start, windowTail)
                                          : advanceWithHistory(step, v, start, full))
                .velocity;
        t += step.h;
        step.h = h;
        const Vec3 exact(1 - s0 * exactRelativeVelocity(c, 1, 0, t), 0,
                         exactRelativeVelocity(c, 0, g, t));
        error = std::max(error, (v - exact).norm());
    }
    return error;
}

/// Errors at h, h/2, h/4, … over a fixed end time; prints them and returns the last order.
double observedOrder(Scheme scheme, const Case& c, double s0, double g, const char* label,
                     double firstStep = 1) {
    const double endTime = 1.0;
    double previous = 0, order = 0;
    std::printf("%s, %s:\n", label, nameOf(scheme).c_str());
    for (long steps = 40; steps <= 5120; steps *= 2) {
        const double error = maxError(scheme, c, s0, g, endTime / steps, steps, 1e-10, firstStep);
        if (previous > 0) order = std::log2(previous / error);
        std::printf("  h = 1/%-4ld max error %.3e  order %.2f\n", steps, error, order);
        previous = error;
    }
    return order;
}

TEST(HistoryClosedForm, ReferenceIntegratorConvergesToTheErfcSolution) {
    // The formula and the integrators check each other: at h = 1/5120 the second-order
    // reference (error ≈ 4e-7 from the orders below, 10⁻⁶ of the 0.3 m/s slip) matches the erfc
    // solution to 1e-6 m/s; a wrong root or sign in the formula gives errors of order 0.1 m/s.
    for (const Case& c : {light, heavy})
        EXPECT_LT(maxError(Scheme::reference2, c, 0.3, c.gravity(), 1.0 / 5120, 5120), 1e-6)
            << "ρp = " << c.particleDensity;
}

struct OrderCase {
    Scheme scheme;
    double startSlip; ///< s0 [m/s]
    bool gravity;
    double low, high; ///< accepted band of the measured order
    bool isHeavy = false;
};

class HistoryOrders : public ::testing::TestWithParam<OrderCase> {};

TEST_P(HistoryOrders, MeasuredOrderMatchesDesign) {
    // The error expands in powers of √h (h², h^2.5, … for order 2: the solution carries t^(k/2)
    // terms), so the measured order approaches its design value as 2 − O(√h): 1.62, 1.71, …,
    // 1.94 from h = 1/40 to 1/5120. Band: design order −0.15 / +0.1 at the finest pair. The naive
    // start (product trapezoid on the slip itself, Maxey's s0/√t term left to the quadrature)
    // makes a first-step error O(h) in v (s − s0 ∝ √t is not linear on [0, h]): order ≈ 1.
    const OrderCase& p = GetParam();
    const Case& c = p.isHeavy ? heavy : light;
    const std::string label = std::string(p.isHeavy ? "heavy, " : "light, ") +
                              (p.startSlip != 0 ? "initial slip" : "released with the gas") +
                              (p.gravity ? ", gravity" : "");
    const double order =
        observedOrder(p.scheme, c, p.startSlip, p.gravity ? c.gravity() : 0.0, label.c_str());
    EXPECT_GE(order, p.low);
    EXPECT_LE(order, p.high);
}

INSTANTIATE_TEST_SUITE_P(
    EveryScheme, HistoryOrders,
    ::testing::Values(OrderCase{Scheme::reference1, 0.0, true, 0.85, 1.1},
                      OrderCase{Scheme::reference2, 0.0, true, 1.85, 2.1},
                      OrderCase{Scheme::windowTail, 0.0, true, 1.85, 2.1},
                      OrderCase{Scheme::reference1, 0.3, false, 0.85, 1.1},
                      OrderCase{Scheme::reference2, 0.3, false, 1.85, 2.1},
                      OrderCase{Scheme::windowTail, 0.3, true, 1.85, 2.1},
                      OrderCase{Scheme::reference2NaiveStart, 0.3, false, 0.8, 1.2},
                      OrderCase{Scheme::reference1, 0.3, true, 0.85, 1.1, true},
                      OrderCase{Scheme::reference2, 0.0, true, 1.85, 2.1, true},
                      OrderCase{Scheme::windowTail, 0.3, true, 1.85, 2.1, true},
                      OrderCase{Scheme::reference2NaiveStart, 0.3, true, 0.8, 1.2, true}));

TEST(HistoryOrders, ShortFirstStepKeepsTheOrder) {
    // A particle released 0.4 h before the step's end (rate injection) takes a first step of
    // 0.4 h: with the first interval weighed for its length the order stays that of a full first
    // step (band as above, −0.2 for the extra early error), and so does the error at the finest
    // step (within 1.5×; weighing it for h made it 9× larger, at order 1.4, without gravity).
    for (const Scheme scheme : {Scheme::reference2, Scheme::windowTail}) {
        const double order = observedOrder(scheme, light, 0.3, light.gravity(),
                                           "light, initial slip, gravity, "
                                           "first step 0.4 h",
                                           0.4);
        EXPECT_GE(order, 1.65);
        EXPECT_LE(order, 2.1);
        const double h = 1.0 / 5120;
        EXPECT_LT(maxError(scheme, light, 0.3, light.gravity(), h, 5120, 1e-10, 0.4),
                  1.5 * maxError(scheme, light, 0.3, light.gravity(), h, 5120));
    }
}

TEST(HistoryWindowTail, StaysWithinItsAccuracyOverALongRun) {
    // 10⁵ steps of h = τ/200 up to t = 500 τ, with initial slip and gravity: the kernel's
    // relative error ≤ 1e-3 bounds the history term's error by 1e-3 of itself, and the history
    // term is at most the slip scale (0.3 m/s here, and the terminal slip ≈ 1.3 m/s), so the
    // velocity stays within 1e-3 × 1.3 m/s of the erfc solution; the discretisation error at this
    // step is ~1e-7 (the orders above). Memory: a fixed number of doubles per particle, 16
    // terms over these five decades of lag with the lowest rates lumped into one (29 without).
    const Case& c = light;
    const double h = 1.0 / c.dragRate() / 200;
    const long steps = 100000;
    const double accuracy = 1e-3;
    const WindowTailLayout layout = WindowTailLayout::make(h, h * steps, accuracy);
    std::printf("window %d steps, %zu exponential terms, %zu bytes per particle\n", layout.window,
                layout.tail.size(), layout.doubles() * sizeof(double));
    EXPECT_LE(layout.tail.size(), 16u);
    const double error = maxError(Scheme::windowTail, c, 0.3, c.gravity(), h, steps, accuracy);
    const double terminalSlip = std::abs(c.gravity() / c.dragRate());
    std::printf("max error over %ld steps: %.3e m/s (%.2e of the terminal slip)\n", steps, error,
                error / terminalSlip);
    EXPECT_LT(error, accuracy * terminalSlip);
}

/// Max |v_a − v_b| over `steps` steps of h of two memories fed the same inputs: the light
/// particle released 0.3 m/s slower than still gas, under gravity.
template <typename MemoryA, typename MemoryB>
double maxDeviation(MemoryA& a, MemoryB& b, double h, long steps) {
    const Case& c = light;
    SlipStep step;
    step.h = h;
    step.dragRate = c.dragRate();
    step.historyRate = c.historyRate();
    step.forceStart = step.forceEnd = Vec3(0, 0, c.gravity());
    Vec3 va(0.3, 0, 0), vb = va;
    HistoryStart startA{-va, 0, Vec3::Zero()}, startB = startA;
    double deviation = 0;
    for (long n = 0; n < steps; ++n) {
        va = advanceWithHistory(step, va, startA, a).velocity;
        vb = advanceWithHistory(step, vb, startB, b).velocity;
        deviation = std::max(deviation, (va - vb).norm());
    }
    return deviation;
}

TEST(HistoryWindowTail, FollowsTheFullMemoryReference) {
    // Same steps, same inputs, 2·10⁴ steps: the two differ only by the tail's kernel error, so
    // |v_tail − v_ref| ≤ accuracy × (history term ≤ terminal slip) for each accuracy target.
    const Case& c = light;
    const double h = 1.0 / c.dragRate() / 200;
    const long steps = 20000;
    const double terminalSlip = std::abs(c.gravity() / c.dragRate());
    for (const double accuracy : {1e-2, 1e-3, 1e-5}) {
        const WindowTailLayout layout = WindowTailLayout::make(h, h * steps, accuracy);
        std::vector<double> tailState(layout.doubles(), 0.0);
        WindowTailHistory windowTail(layout, tailState.data());
        FullHistory full(h, 2);
        const double deviation = maxDeviation(windowTail, full, h, steps);
        std::printf("accuracy %.0e: window %d, %zu terms, max |v_tail − v_ref| %.2e m/s\n",
                    accuracy, layout.window, layout.tail.size(), deviation);
        EXPECT_LT(deviation, accuracy * terminalSlip);
    }
}

TEST(HistoryWindowTail, SinglePrecisionSumsStayWithinATenthOfTheAccuracy) {
    // The fastest terms' sums are kept in float (WindowTailLayout::singleTerms). Rounded each
    // step, a sum decaying by e^{−h/θ} can stall at most 2⁻²⁴ θ/h of itself from its value, and
    // the layout keeps that below accuracy/10; the sums add up to at most the history integral of
    // |ρ|, itself at most the terminal slip's (gravity, released with slip). So the velocities
    // with and without the single sums differ by at most accuracy/10 of the terminal slip, over
    // 10⁵ steps that end near the terminal slip (ρ constant: where a stall would show).
    const Case& c = light;
    const double h = 1.0 / c.dragRate() / 200;
    const long steps = 100000;
    const double terminalSlip = std::abs(c.gravity() / c.dragRate());
    for (const double accuracy : {1e-2, 1e-3, 1e-4}) {
        const WindowTailLayout mixed = WindowTailLayout::make(h, h * steps, accuracy);
        WindowTailLayout allDouble = mixed;
        allDouble.singleTerms = 0;
        ASSERT_GT(mixed.singleTerms, 0u);
        std::vector<double> mixedState(mixed.doubles(), 0.0), doubleState(allDouble.doubles(), 0.0);
        WindowTailHistory mixedMemory(mixed, mixedState.data());
        WindowTailHistory doubleMemory(allDouble, doubleState.data());
        const double deviation = maxDeviation(mixedMemory, doubleMemory, h, steps);
        std::printf("accuracy %.0e: %zu of %zu terms single, %zu against %zu bytes, max |Δv| "
                    "%.2e m/s (%.1e of the terminal slip)\n",
                    accuracy, mixed.singleTerms, mixed.tail.size(), mixed.doubles() * 8,
                    allDouble.doubles() * 8, deviation, deviation / terminalSlip);
        EXPECT_LT(deviation, accuracy / 10 * terminalSlip);
    }
}

TEST(HistoryWindowTail, ExponentialSumMeetsItsTargetOverTheWholeRange) {
    // Relative error of the fitted sum against 1/√ℓ on a log grid over [window, horizon].
    for (const double accuracy : {1e-2, 1e-3, 1e-6}) {
        const ExponentialSum sum = ExponentialSum::fit(1e-3, 1e3, accuracy);
        double worst = 0;
        for (double lag = 1e-3; lag <= 1e3; lag *= 1.05)
            worst = std::max(worst, std::abs(sum(lag) * std::sqrt(lag) - 1));
        std::printf("accuracy %.0e: %zu terms, worst relative error %.2e\n", accuracy, sum.size(),
                    worst);
        EXPECT_LT(worst, accuracy);
    }
}

TEST(HistoryKernels, FiniteReynoldsKernelsStartAsBassetAndDecayAsLagSquared) {
    // Mei & Adrian (Eq. 3.5) and Kim et al. (Eq. 3.9) equal Basset's R/√(πνℓ) for ℓ → 0 and fall
    // as ℓ^(−2) for ℓ → ∞ (their design; Mei & Adrian 1992 Eq. 16).
    const double radius = 50e-6, viscosity = 1.5e-5, slip = 1.0;
    for (const auto& kernel : std::vector<std::function<double(double)>>{
             [&](double lag) { return meiAdrianKernel(lag, slip, radius, viscosity); },
             [&](double lag) { return kimKernel(lag, slip, radius, viscosity, 1.0); }}) {
        const double shortLag = 1e-12;
        EXPECT_NEAR(kernel(shortLag) / bassetKernel(shortLag, radius, viscosity), 1.0, 1e-2);
        EXPECT_NEAR(kernel(20.0) / kernel(10.0), 0.25, 0.01);
        EXPECT_LT(kernel(1e-3), bassetKernel(1e-3, radius, viscosity));
    }
}

} // namespace
} // namespace slides
