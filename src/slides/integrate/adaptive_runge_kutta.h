// Adaptive embedded Runge–Kutta: the Dormand–Prince 5(4) pair (Dormand & Prince 1980; Hairer,
// Nørsett & Wanner, Solving ODEs I, Table II.5.2) with the step controlled per particle
// (Section 4.2.3, Eq. 4.18–4.29, Algorithm 2), for the particle equation of motion
// dv/dt = (u(x) − v)/τ + a, dx/dt = v of integrate/integrator.h, where u varies along the
// step (the exponential schemes freeze it).
//
// Eq. 4.19–4.20 with the tableau below give the 5th-order solution; the 4th-order one shares
// its stages, and their difference h Σ (b_j − b̂_j) k_j (Eq. 4.28) estimates the error of the
// 4th-order one. Its size is measured component by component against the tolerance TOL
// scaled to the particle: a position against TOL × (its radius), a velocity against TOL ×
// (its speed, or the gas speed if larger), as a root mean square over the six (Hairer's
// norm). A step of error ≤ 1 is accepted (the 5th-order solution kept: local extrapolation);
// either way the next is h (0.9 / error)^(1/5) (Eq. 4.29 with β_safe = 0.9), at most 5 and
// at least 0.2 times h, and never beyond the end of the global step: particles sub-step within
// the global step, so frames and collisions see them all at its end.
//
// A step function over one particle's (x, v) and its right-hand side; over a batch in a carrier:
// integrate/adaptive_runge_kutta_batch.h; in a run: `time { integrator adaptiveRungeKutta;
// tolerance 1e-6; }` (run/stepper.h).
#pragma once

#include "slides/core/vector.h"

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace slides {

/// (x, v) of one particle.
using MotionState = Eigen::Matrix<double, 6, 1>;

/// The Dormand–Prince 5(4) tableau (Eq. 4.18): c, a, the 5th-order weights b and the
/// 4th-order weights b̂.
struct DormandPrince {
    static constexpr int stages = 7;
    static constexpr std::array<double, 7> c{0, 1.0 / 5, 3.0 / 10, 4.0 / 5, 8.0 / 9, 1, 1};
    static constexpr std::array<std::array<double, 6>, 7> a{{
        {},
        {1.0 / 5},
        {3.0 / 40, 9.0 / 40},
        {44.0 / 45, -56.0 / 15, 32.0 / 9},
        {19372.0 / 6561, -25360.0 / 2187, 64448.0 / 6561, -212.0 / 729},
        {9017.0 / 3168, -355.0 / 33, 46732.0 / 5247, 49.0 / 176, -5103.0 / 18656},
        {35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84},
    }};
    static constexpr std::array<double, 7> b{
        35.0 / 384, 0, 500.0 / 1113, 125.0 / 192, -2187.0 / 6784, 11.0 / 84, 0};
    static constexpr std::array<double, 7> bLower{
        5179.0 / 57600, 0, 7571.0 / 16695, 393.0 / 640, -92097.0 / 339200, 187.0 / 2100, 1.0 / 40};
};

/// Step-size factor of Eq. 4.29 for an error (in units of the tolerance): β_safe error^(−1/5),
/// bounded to [0.2, 5].
inline double stepFactor(double error) {
    if (!(error > 0)) return 5.0;
    return std::clamp(0.9 * std::pow(error, -0.2), 0.2, 5.0);
}

/// Whether a sub-step of length step (of the global share length) with this error is kept:
/// within the tolerance, or too short to shrink further, or not finite — a non-finite state
/// then reaches the stepper's check, which stops the run naming the particle, instead of
/// being rejected without end.
inline bool keepsStep(double error, double step, double length) {
    return error <= 1 || !std::isfinite(error) || step <= 1e-12 * length;
}

/// The stage state y + h Σ_{j<s} a_sj k_j (Eq. 4.19).
inline MotionState stageState(const MotionState& y, const std::array<MotionState, 7>& k, int s,
                              double h) {
    MotionState stage = y;
    for (int j = 0; j < s; ++j) stage += h * DormandPrince::a[s][j] * k[j];
    return stage;
}

/// The 5th-order solution (Eq. 4.20) and the error estimate h Σ (b_j − b̂_j) k_j (Eq. 4.28).
inline void combineStages(const MotionState& y, const std::array<MotionState, 7>& k, double h,
                          MotionState& next, MotionState& error) {
    next = y;
    error.setZero();
    for (int j = 0; j < DormandPrince::stages; ++j) {
        next += h * DormandPrince::b[j] * k[j];
        error += h * (DormandPrince::b[j] - DormandPrince::bLower[j]) * k[j];
    }
}

/// The error in units of the tolerance: rms over the components of error / scale.
inline double scaledError(const MotionState& error, const MotionState& scale) {
    return std::sqrt((error.array() / scale.array()).square().mean());
}

/// The scale of a particle's error: TOL × radius for a position, TOL × the larger of its
/// speeds and the gas speed for a velocity; never below 4 ε of the state and of its change over
/// the sub-step, the rounding of double precision in them: a tolerance finer than that (1e-300,
/// say) ends the sub-steps where the state can tell no more, instead of shrinking them to the
/// floor of keepsStep and taking 10¹² of them.
inline MotionState errorScale(double tolerance, double radius, const MotionState& from,
                              const MotionState& to, double gasSpeed) {
    constexpr double rounding = 4 * std::numeric_limits<double>::epsilon();
    const double speed = std::max({from.tail<3>().norm(), to.tail<3>().norm(), gasSpeed});
    const double position = std::max(from.head<3>().norm(), to.head<3>().norm());
    const double moved = (to.head<3>() - from.head<3>()).norm();
    const double accelerated = (to.tail<3>() - from.tail<3>()).norm();
    MotionState scale;
    scale.head<3>().setConstant(std::max(tolerance * radius, rounding * (position + moved)));
    scale.tail<3>().setConstant(
        std::max(tolerance * std::max(speed, 1e-300), rounding * (speed + accelerated)));
    return scale;
}

/// Advances y over h (the global step's share) by accepted Dormand–Prince steps controlled by
/// the tolerance, for a right-hand side f(t, y) and its error scale scaleOf(y0, y1); trial is
/// the first step to try and returns the next. Returns the number of attempted steps.
template <typename RightHandSide, typename Scale>
int advanceAdaptively(MotionState& y, double t, double h, double& trial, RightHandSide f,
                      Scale scaleOf) {
    std::array<MotionState, 7> k;
    double done = 0;
    int attempts = 0;
    while (done < h) {
        const double step = std::min(trial, h - done);
        for (int s = 0; s < DormandPrince::stages; ++s)
            k[s] = f(t + done + DormandPrince::c[s] * step, stageState(y, k, s, step));
        MotionState next, error;
        combineStages(y, k, step, next, error);
        const double size = scaledError(error, scaleOf(y, next));
        ++attempts;
        trial = step * stepFactor(size);
        if (keepsStep(size, step, h)) {
            y = next;
            done += step;
        }
    }
    return attempts;
}

} // namespace slides
