// ctest-labels: adaptive
// Adaptive embedded Runge–Kutta (integrate/adaptive_runge_kutta.h; Section 4.2.3, Eq. 4.18–4.29,
// Algorithm 2) on the particle equation dv/dt = (u(x) − v)/τ + a, dx/dt = v:
// - orders: in a straining flow u = k x (linear, closed form x = Σ A e^(λt), τλ² + λ − k = 0)
//   the fixed-step 5th- and 4th-order solutions of the Dormand–Prince pair lose 2^5 and 2^4 of
//   their error per halving of the step;
// - the controlled error: the global error of the adaptive solution stays below TOL (each
//   step's local error is held below TOL and the kept 5th-order solution is better still), but
//   within three decades of it (the control does not over-resolve), and falls with TOL;
// - against the exponential integrators (integrate/integrator.h relaxExactly): in a uniform gas
//   with gravity the exact relaxation and the adaptive steps agree to TOL;
// - a batch in a carrier (integrate/adaptive_runge_kutta_batch.h) sub-steps each particle as
//   the step function does alone, and every particle ends at the end of the global step;
// - stiff: τ ≪ h (a 1 µm particle, τ = 3 µs, over h = 1 ms) takes more steps than τ ≈ h, and
//   stays stable (explicit stability limits a step to about 3.3 τ) at the terminal velocity.
#include "slides/integrate/adaptive_runge_kutta.h"
#include "slides/integrate/adaptive_runge_kutta_batch.h"
#include "slides/integrate/integrator.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace slides;

namespace {

/// dv/dt = (u(x) − v)/τ + a with u = k x (along x only) and constant τ, a.
struct Straining {
    double strain, responseTime;
    Vec3 acceleration = Vec3::Zero();
    MotionState operator()(double, const MotionState& y) const {
        MotionState dy;
        dy.head<3>() = y.tail<3>();
        const Vec3 gas = strain * Vec3(y[0], 0, 0);
        dy.tail<3>() = (gas - Vec3(y.tail<3>())) / responseTime + acceleration;
        return dy;
    }
    /// x(t) from x(0) = 1, v(0) = 0 along the strain axis (closed form).
    double exactPosition(double t) const {
        const double root = std::sqrt(1 + 4 * responseTime * strain);
        const double fast = (-1 - root) / (2 * responseTime),
                     slow = (-1 + root) / (2 * responseTime);
        // x = A e^(slow t) + B e^(fast t), A + B = 1, A slow + B fast = 0.
        const double A = -fast / (slow - fast), B = slow / (slow - fast);
        return A * std::exp(slow * t) + B * std::exp(fast * t);
    }
};

MotionState startAtOne() {
    MotionState y = MotionState::Zero();
    y[0] = 1;
    return y;
}

/// Fixed steps of the pair over [0, T]: the 5th-order (upper) or the 4th-order solution.
double fixedStepPosition(const Straining& f, double T, int steps, bool upper) {
    MotionState y = startAtOne();
    const double h = T / steps;
    std::array<MotionState, 7> k;
    for (int n = 0; n < steps; ++n) {
        for (int s = 0; s < DormandPrince::stages; ++s)
            k[s] = f(n * h + DormandPrince::c[s] * h, stageState(y, k, s, h));
        MotionState next, error;
        combineStages(y, k, h, next, error);
        y = upper ? next : MotionState(next - error);
    }
    return y[0];
}

} // namespace

TEST(AdaptiveRungeKutta, FixedStepsConvergeAtOrdersFiveAndFour) {
    const Straining f{50.0, 0.01}; // λ = 41.4 and −141.4 per second
    const double T = 0.05;
    for (const bool upper : {true, false}) {
        const int order = upper ? 5 : 4;
        const double coarse = std::abs(fixedStepPosition(f, T, 20, upper) - f.exactPosition(T));
        const double fine = std::abs(fixedStepPosition(f, T, 40, upper) - f.exactPosition(T));
        // Observed order log2(coarse/fine) within 0.3 of the design order (the next term of
        // the error's expansion is one order smaller by h λ ≈ 0.35 at this step).
        EXPECT_NEAR(std::log2(coarse / fine), order, 0.3) << "order " << order;
    }
}

TEST(AdaptiveRungeKutta, GlobalErrorFollowsTheTolerance) {
    const Straining f{50.0, 0.01};
    const double T = 0.05;
    double previous = 1;
    for (const double tolerance : {1e-3, 1e-5, 1e-7, 1e-9}) {
        MotionState y = startAtOne();
        double trial = T;
        const int attempts =
            advanceAdaptively(y, 0, T, trial, f, [&](const MotionState&, const MotionState&) {
                return MotionState::Constant(tolerance);
            });
        const double error = std::abs(y[0] - f.exactPosition(T));
        // Measured: error / TOL = 0.0025, 0.0066, 0.0088, 0.0097 in 11, 22, 49, 115 steps
        // (the 5th-order solution is kept while the 4th-order one's error is controlled).
        EXPECT_LE(error, tolerance) << tolerance;
        EXPECT_GE(error, 1e-3 * tolerance) << tolerance << ": resolved far beyond the tolerance";
        EXPECT_GE(attempts, 10);
        EXPECT_LT(error, 0.03 * previous);
        previous = error;
    }
}

TEST(AdaptiveRungeKutta, AgreesWithTheExactRelaxationInAUniformGas) {
    // Uniform gas 3 m/s along x, gravity; τ = 1 ms, one global step of 5 ms (h ≫ τ).
    const double tau = 1e-3, h = 5e-3, tolerance = 1e-8;
    const Vec3 gas(3, 0, 0), gravity(0, -9.81, 0);
    const auto f = [&](double, const MotionState& y) {
        MotionState dy;
        dy.head<3>() = y.tail<3>();
        dy.tail<3>() = (gas - Vec3(y.tail<3>())) / tau + gravity;
        return dy;
    };
    MotionState y = MotionState::Zero();
    y.tail<3>() = Vec3(0, 2, 1);
    Vec3 x = y.head<3>(), v = y.tail<3>();
    relaxExactly(x, v, gas, tau, gravity, h);
    const double radius = 10e-6;
    double trial = h;
    advanceAdaptively(y, 0, h, trial, f, [&](const MotionState& from, const MotionState& to) {
        return errorScale(tolerance, radius, from, to, gas.norm());
    });
    // Measured: 0.47 TOL × radius and 0.0016 TOL × gas speed.
    EXPECT_LT((Vec3(y.head<3>()) - x).norm(), 2 * tolerance * radius);
    EXPECT_LT((Vec3(y.tail<3>()) - v).norm(), tolerance * gas.norm());
}

TEST(AdaptiveRungeKutta, StiffDragTakesMoreStepsButStaysStable) {
    const double h = 1e-3, tolerance = 1e-6;
    const Vec3 gas(3, 0, 0);
    const auto attemptsFor = [&](double tau, MotionState& y) {
        const auto f = [&](double, const MotionState& state) {
            MotionState dy;
            dy.head<3>() = state.tail<3>();
            dy.tail<3>() = (gas - Vec3(state.tail<3>())) / tau;
            return dy;
        };
        y = MotionState::Zero();
        double trial = h;
        return advanceAdaptively(y, 0, h, trial, f,
                                 [&](const MotionState& from, const MotionState& to) {
                                     return errorScale(tolerance, 1e-6, from, to, gas.norm());
                                 });
    };
    MotionState slow, stiff;
    const int relaxed = attemptsFor(1e-3, slow);
    const int many = attemptsFor(3e-6, stiff);
    // Stability alone needs h / (3.3 τ) ≈ 100 steps; measured 138 against 19.
    EXPECT_GT(many, 100);
    EXPECT_GT(many, 5 * relaxed);
    ASSERT_TRUE(stiff.allFinite());
    EXPECT_NEAR(stiff[3], 3.0, 1e-5); // relaxed to the gas: e^(−333) of the slip left
    EXPECT_NEAR(stiff[4], 0.0, 1e-5);
}

namespace {

/// Plane stagnation-point flow with a swirl, U = (−s x − w y, s y + w x, 0) + (1 0 0) m/s.
class SwirlingFlow : public CarrierField {
public:
    Vec3 at(const Vec3& x) const {
        return Vec3(-strain * x[0] - swirl * x[1] + 1, strain * x[1] + swirl * x[0], 0);
    }
    void sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                CarrierSample& out) const override {
        out.resize(points.size(), needs);
        for (std::size_t i = 0; i < points.size(); ++i) out.velocity[i] = at(points[i]);
    }
    std::string describe() const override { return "swirling stagnation flow"; }
    double strain = 200, swirl = 100; ///< [1/s]
};

} // namespace

TEST(AdaptiveRungeKutta, ABatchSubStepsEachParticleAsAloneAndAllEndTogether) {
    // Particles of 2 µm to 60 µm (τ from 30 µs to 27 ms in air), one of them injected within
    // the step (a share of 0.4 of it); one 1 ms step at TOL = 1e-7.
    const SwirlingFlow flow;
    const DragParameters drag{DragModel::haiderLevenspiel, 1.2, 1.5e-5, 2500};
    const Vec3 gravity(0, -9.81, 0);
    const double tolerance = 1e-7, dt = 1e-3;
    std::vector<Vec3> x{{0.01, 0.002, 0}, {-0.003, 0.001, 0.001}, {0.002, -0.004, 0}, {0, 0, 0}};
    std::vector<Vec3> v{{0, 0, 0}, {1, 0, 0}, {0.5, 0.5, 0}, {0, 0, 1}};
    const std::vector<double> radius{2e-6, 10e-6, 30e-6, 60e-6}, h{dt, dt, 0.4 * dt, dt};
    std::vector<Vec3> xBatch = x, vBatch = v;
    const AdaptiveSteps steps =
        advanceAdaptiveBatch({xBatch, vBatch, radius, h}, 0.0, tolerance, drag, gravity, flow);
    EXPECT_GT(steps.attempted, 4 * 4); // it sub-stepped: measured 76 steps, 5 rejected
    long attempted = 0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const auto f = [&](double, const MotionState& y) {
            MotionState dy;
            const Vec3 slip = flow.at(y.head<3>()) - Vec3(y.tail<3>());
            dy << y.tail<3>(), slip / dragResponseTime(drag, radius[i], slip.norm()) + gravity;
            return dy;
        };
        MotionState y;
        y << x[i], v[i];
        double trial = h[i];
        attempted += advanceAdaptively(
            y, 0, h[i], trial, f, [&](const MotionState& from, const MotionState& to) {
                return errorScale(tolerance, radius[i], from, to, flow.at(to.head<3>()).norm());
            });
        EXPECT_EQ(xBatch[i], Vec3(y.head<3>())) << i;
        EXPECT_EQ(vBatch[i], Vec3(y.tail<3>())) << i;
    }
    EXPECT_EQ(steps.attempted, attempted);
}
