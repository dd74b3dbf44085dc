// ctest-labels: history physics
// The finite-Reynolds history memories (physics/finite_reynolds_history.h) for Mei & Adrian's
// kernel (Eq. 3.4–3.7) and Kim's (Eq. 3.8–3.15):
//  - the quadrature A(t) = s(0) Q(t; ℓ_c(0)) + ∫ Q(t − τ; ℓ_c(τ)) ds(τ) of a prescribed slip
//    whose speed, and so ℓ_c, varies, against direct quadrature: order 2 under step halving,
//    for the reference and the window + tail, and the tail within its accuracy over 10⁵ steps;
//  - the equation of motion (drag, history) under step halving: order 2 for a release with the
//    flow, and for a release with slip the error with the start mode against without.
#include "slides/physics/finite_reynolds_history.h"
#include "slides/physics/history_kernel.h"
#include "slides/physics/unsteady.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace slides {
namespace {

/// A 50 µm sphere in air; the slip's speed 0.3 … 1 m/s makes ℓ_c ≈ 30 … 200 µs, so over
/// T = 1 ms the kernel has left Basset's form for the ℓ^(−2) decay.
constexpr double radius = 50e-6, viscosity = 1.5e-5, period = 1e-3;
constexpr double omega = 2 * std::numbers::pi * 2 / period;

Vec3 slipAt(double t) { return {0.6 + 0.4 * std::sin(omega * t), 0.3 * std::cos(omega * t), 0}; }
Vec3 slipRate(double t) {
    return {0.4 * omega * std::cos(omega * t), -0.3 * omega * std::sin(omega * t), 0};
}

SlipKernel kernelOf(const FiniteReynoldsShape& shape) {
    return {&FiniteReynoldsKernel::of(shape), radius, viscosity};
}

/// A(t) by direct quadrature: the jump, and ∫_0^t Q(t − τ; ℓ_c(s(τ))) ṡ(τ) dτ in τ = t − u²
/// (the integrand 2u Q(u²) ṡ is C³ at u = 0) by 8-point Gauss–Legendre on `panels` panels.
Vec3 directIntegral(const SlipKernel& kernel, double t, int panels) {
    static constexpr std::array<double, 4> node{0.1834346424956498, 0.5255324099163290,
                                                0.7966664774136267, 0.9602898564975363};
    static constexpr std::array<double, 4> weight{0.3626837833783620, 0.3137066458778873,
                                                  0.2223810344533745, 0.1012285362903763};
    const FiniteReynoldsKernel& tables = *kernel.tables;
    Vec3 sum = tables.firstIntegral(t, kernel.crossover(slipAt(0))) * slipAt(0);
    const double top = std::sqrt(t), width = top / panels;
    for (int k = 0; k < panels; ++k) {
        for (std::size_t i = 0; i < node.size(); ++i) {
            for (const double side : {-1.0, 1.0}) {
                const double u = (k + 0.5 + 0.5 * side * node[i]) * width;
                const double tau = t - u * u;
                sum += 0.5 * width * weight[i] * 2 * u *
                       tables.firstIntegral(u * u, kernel.crossover(slipAt(tau))) * slipRate(tau);
            }
        }
    }
    return sum;
}

/// A at t = steps h from the memory fed with the exact slips.
template <typename Memory> Vec3 memoryIntegral(Memory& memory, double h, long steps) {
    Vec3 integral = Vec3::Zero();
    for (long n = 1; n <= steps; ++n) {
        const Vec3 known = memory.beginStep(h);
        const Vec3 slip = slipAt(n * h);
        integral = known + memory.newestWeight() * slip;
        memory.endStep(slip);
    }
    return integral;
}

struct WindowTailRun {
    FiniteReynoldsLayout layout;
    std::vector<double> state;
    FiniteReynoldsWindowTail memory;
    WindowTailRun(const SlipKernel& kernel, double h, double horizon, double accuracy)
        : layout(FiniteReynoldsLayout::make(
              WindowTailLayout::make(h, horizon, accuracy, LowRates::truncated), horizon)),
          state(layout.doubles()), memory(layout, state.data(), kernel) {
        memory.start(slipAt(0), kernel.crossover(slipAt(0)));
    }
};

TEST(FiniteReynoldsHistory, QuadratureOfAVaryingSlipConvergesAtSecondOrder) {
    for (const auto& shape : {meiAdrianShape, kimShape}) {
        const SlipKernel kernel = kernelOf(shape);
        const Vec3 exact = directIntegral(kernel, period, 4000);
        std::printf("c1 = %.1f, |A(T)| = %.4e √s m/s\n", shape.exponent, exact.norm());
        double previousFull = 0, previousTail = 0, orderFull = 0, orderTail = 0;
        for (long steps = 25; steps <= 1600; steps *= 2) {
            const double h = period / steps;
            FiniteReynoldsFullHistory full(kernel, slipAt(0), kernel.crossover(slipAt(0)));
            WindowTailRun tail(kernel, h, period, 1e-9);
            const double errorFull = (memoryIntegral(full, h, steps) - exact).norm() / exact.norm();
            const double errorTail =
                (memoryIntegral(tail.memory, h, steps) - exact).norm() / exact.norm();
            if (previousFull > 0) {
                orderFull = std::log2(previousFull / errorFull);
                orderTail = std::log2(previousTail / errorTail);
            }
            std::printf("  h = T/%-5ld reference %.3e (order %.2f)  window + tail %.3e (order "
                        "%.2f)\n",
                        steps, errorFull, orderFull, errorTail, orderTail);
            previousFull = errorFull;
            previousTail = errorTail;
        }
        EXPECT_NEAR(orderFull, 2.0, 0.15);
        EXPECT_NEAR(orderTail, 2.0, 0.15);
    }
}

TEST(FiniteReynoldsHistory, WindowTailStaysWithinItsAccuracyOverLongRuns) {
    // 10⁵ steps of h = T/1000 (100 periods of the slip): the tail fitted to 1e-3 relative of
    // Basset's kernel against one fitted to 1e-10 (the tail's own error), and both against
    // direct quadrature (that and the quadrature's O(h²), ~2.5e-5 by the test above).
    const SlipKernel kernel = kernelOf(meiAdrianShape);
    const double h = period / 1000;
    const long steps = 100000;
    const double accuracy = 1e-3;
    WindowTailRun tail(kernel, h, steps * h, accuracy), fine(kernel, h, steps * h, 1e-10);
    double worstTail = 0, worstTotal = 0;
    Vec3 integral = Vec3::Zero(), fineIntegral = Vec3::Zero();
    for (long n = 1; n <= steps; ++n) {
        const Vec3 slip = slipAt(n * h);
        integral = tail.memory.beginStep(h) + tail.memory.newestWeight() * slip;
        fineIntegral = fine.memory.beginStep(h) + fine.memory.newestWeight() * slip;
        tail.memory.endStep(slip);
        fine.memory.endStep(slip);
        const double tailError = (integral - fineIntegral).norm() / fineIntegral.norm();
        worstTail = std::max(worstTail, tailError);
        if (n % 20000 == 0) {
            // The exact A by direct quadrature, with ~100 panels a period near u = √t.
            const Vec3 exact = directIntegral(kernel, n * h, static_cast<int>(n / 2));
            const double error = (integral - exact).norm() / exact.norm();
            std::printf("  step %6ld: |A| %.4e, relative error %.2e, of the tail %.2e\n", n,
                        exact.norm(), error, tailError);
            worstTotal = std::max(worstTotal, error);
        }
    }
    std::printf("  %zu terms, %zu doubles a particle; worst tail error %.2e\n",
                tail.layout.base.tail.size(), tail.layout.doubles(), worstTail);
    EXPECT_LT(worstTail, accuracy);
    EXPECT_LT(worstTotal, accuracy);
}

/// A glass sphere (R = 0.5 mm, ρp = 2500) in water, Stokes drag per effective mass, and the gas
/// either turning from rest, u = U (sin Ωt, 1 − cos Ωt, 0), so that the slip turns with it and
/// never vanishes after the start, or a uniform stream U (1, ½, 0) into which the sphere is
/// released at rest. Re ≈ 5 makes ℓ_c ≈ 17 ms against a run of 0.4 s.
struct Sphere {
    double fluidDensity = 1000, particleDensity = 2500, viscosity = 1e-6, radius = 5e-4;
    double speed = 0.01, frequency = 2 * std::numbers::pi / 0.2, endTime = 0.4;
    Vec3 gasAt(double t, bool stream) const {
        if (stream) return speed * Vec3(1, 0.5, 0);
        return speed * Vec3(std::sin(frequency * t), 1 - std::cos(frequency * t), 0);
    }
};

enum class Memory { full, windowTail };

/// v at the end time after `steps` steps, with the kernel's memory of the slip.
Vec3 finalVelocity(const FiniteReynoldsShape& shape, Memory kind, bool stream, long steps,
                   bool startMode = true) {
    const Sphere c;
    const double h = c.endTime / steps;
    const SlipKernel kernel{&FiniteReynoldsKernel::of(shape), c.radius, c.viscosity};
    SlipStep step;
    step.h = h;
    step.dragRate =
        1 / effectiveResponseTime(c.particleDensity, c.fluidDensity, c.viscosity, c.radius, 0.5);
    step.historyRate =
        bassetHistoryRate(c.particleDensity, c.fluidDensity, c.viscosity, c.radius, 0.5);
    Vec3 v = Vec3::Zero();
    const Vec3 releaseSlip = c.gasAt(0, stream) - v;
    const double jump = kernel.crossover(releaseSlip);
    FiniteReynoldsFullHistory full(kernel, releaseSlip, jump);
    const FiniteReynoldsLayout layout = FiniteReynoldsLayout::make(
        WindowTailLayout::make(h, c.endTime, 1e-6, LowRates::truncated), c.endTime);
    std::vector<double> state(layout.doubles());
    FiniteReynoldsWindowTail windowTail(layout, state.data(), kernel);
    windowTail.start(releaseSlip, jump);
    HistoryStart start;
    if (startMode) start.startSlip = releaseSlip; // (zero from rest in the turning gas)
    for (long n = 0; n < steps; ++n) {
        step.gasStart = c.gasAt(n * h, stream);
        step.gasEnd = c.gasAt((n + 1) * h, stream);
        v = (kind == Memory::full ? advanceWithHistory(step, v, start, full)
                                  : advanceWithHistory(step, v, start, windowTail))
                .velocity;
    }
    return v;
}

/// |v_h − v_{h/2}| at the end under step halving, h = T/50 … T/3200, printed with the orders.
std::vector<double> selfConvergence(const FiniteReynoldsShape& shape, Memory kind, bool stream,
                                    bool startMode = true) {
    std::vector<double> errors;
    Vec3 previous = finalVelocity(shape, kind, stream, 25, startMode);
    for (long steps = 50; steps <= 3200; steps *= 2) {
        const Vec3 v = finalVelocity(shape, kind, stream, steps, startMode);
        errors.push_back((v - previous).norm());
        const double order =
            errors.size() > 1 ? std::log2(errors[errors.size() - 2] / errors.back()) : 0;
        std::printf("    h = T/%-5ld |v_h − v_2h| %.3e  order %.2f\n", steps, errors.back(), order);
        previous = v;
    }
    return errors;
}

double selfConvergenceOrder(const FiniteReynoldsShape& shape, Memory kind, bool stream) {
    const std::vector<double> errors = selfConvergence(shape, kind, stream);
    return std::log2(errors[errors.size() - 2] / errors.back());
}

TEST(FiniteReynoldsHistory, EquationOfMotionReleasedWithTheFlowIsSecondOrder) {
    // Design order 2. From zero slip at the start, ℓ_c ∝ 1/|s|² makes the kernel depend on
    // τ^(2p) there (p = 3/4, 0.6), which adds h^(1+2p) terms: measured 1.80 (Mei & Adrian) and
    // 2.35 (Kim) at h = T/3200, still approaching 2 (Mei & Adrian 1.86, 1.90 at T/6400, T/12800).
    for (const auto& shape : {meiAdrianShape, kimShape}) {
        for (const Memory kind : {Memory::full, Memory::windowTail}) {
            std::printf("c1 = %.1f, %s, turning gas from rest:\n", shape.exponent,
                        kind == Memory::full ? "reference" : "window + tail");
            const double order = selfConvergenceOrder(shape, kind, false);
            EXPECT_GT(order, 1.7);
            EXPECT_LT(order, 2.45);
        }
    }
}

TEST(FiniteReynoldsHistory, StartModeCutsTheErrorOfAReleaseWithSlip) {
    // Released at rest into a stream: s − s0 ∝ √t. Without a start mode the slip's linear
    // intervals err O(h^(3/2)) in A for good (order 1.5, measured 1.46 … 1.49). Basset's start
    // mode with the moment correction and ℓ_c averaged per part (physics/
    // finite_reynolds_history.h): errors 42–145 times smaller (Mei & Adrian, orders rising to
    // 1.80 at T/3200, the limit 2 as with ℓ_c frozen), 10–820 (Kim, down to 5e-11 where the
    // orders scatter) over h = T/50 … T/3200; the test holds them below a tenth from T/100.
    for (const auto& shape : {meiAdrianShape, kimShape}) {
        std::printf("c1 = %.1f, reference, released at rest into a stream, naive start:\n",
                    shape.exponent);
        const std::vector<double> naive = selfConvergence(shape, Memory::full, true, false);
        for (const Memory kind : {Memory::full, Memory::windowTail}) {
            std::printf("  %s with the start mode:\n",
                        kind == Memory::full ? "reference" : "window + tail");
            const std::vector<double> started = selfConvergence(shape, kind, true);
            for (std::size_t k = 1; k < naive.size(); ++k)
                EXPECT_LT(started[k], 0.1 * naive[k]) << "level " << k;
        }
    }
}

} // namespace
} // namespace slides
