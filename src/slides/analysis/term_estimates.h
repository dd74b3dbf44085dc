// Term estimates: how much a physics term would change a particle's motion, from the path the
// particle takes without it (first-order perturbation of the equation of motion, Eq. 3.3).
//
// A small extra acceleration a(t) on a particle whose drag relaxes slip with response time τ
// drives a velocity deviation δ with dδ/dt = a − δ/τ: its effect on the result is |δ| over a
// reference speed. The Basset acceleration (Eq. 3.3) follows from the slip path by product
// integration; the turbulent velocity a particle takes on follows Tchen's response; collisions
// per particle follow the kinetic rate n π (2R)² w_rel. The scene analysis
// (analysis/scene_analysis.h) applies them along pilot paths.
#pragma once

#include "slides/core/vector.h"

#include <cmath>
#include <numbers>
#include <span>

namespace slides {

/// δ after h of dδ/dt = a − δ/τ with a frozen (exact, stable for any h).
inline Vec3 relaxDeviation(const Vec3& deviation, const Vec3& acceleration, double responseTime,
                           double h) {
    const double decay = std::exp(-h / responseTime);
    return deviation * decay - acceleration * (responseTime * std::expm1(-h / responseTime));
}

/// Basset history acceleration of a sphere of radius R at time t from its slip w = u − v at
/// times s_0 < s_1 < ... ≤ t, w linear between them, and a jump from 0 to w_0 at s_0 (a
/// particle released with slip): (9 ρf √ν)/(2 ρp R √π) [w_0/√(t − s_0) +
/// Σ (Δw_j/Δs_j) 2(√(t − s_j) − √(t − s_{j+1}))] — F_B = 6R²ρf√(πν) ∫ (dw/ds)/√(t − s) ds of
/// Eq. 3.3 per particle mass. t must exceed s_0.
inline Vec3 bassetAcceleration(std::span<const double> times, std::span<const Vec3> slips, double t,
                               double particleRadius, double particleDensity, double fluidDensity,
                               double kinematicViscosity) {
    Vec3 integral = slips[0] / std::sqrt(t - times[0]);
    for (std::size_t j = 0; j + 1 < times.size() && times[j + 1] <= t; ++j) {
        const double interval = times[j + 1] - times[j];
        if (!(interval > 0)) continue;
        integral += (slips[j + 1] - slips[j]) / interval * 2.0 *
                    (std::sqrt(t - times[j]) - std::sqrt(t - times[j + 1]));
    }
    return 9.0 * fluidDensity * std::sqrt(kinematicViscosity) /
           (2.0 * particleDensity * particleRadius * std::sqrt(std::numbers::pi)) * integral;
}

/// rms velocity fluctuation a particle of response time τ takes on in turbulence of rms u′
/// and Lagrangian time scale T_L with exponential correlation: u′ √(T_L/(T_L + τ)) (Tchen).
inline double particleFluctuation(double fluidRms, double lagrangianTime, double responseTime) {
    if (!(lagrangianTime > 0)) return 0;
    return fluidRms * std::sqrt(lagrangianTime / (lagrangianTime + responseTime));
}

/// Collisions per particle per second in a cloud of number density n, radius R, relative
/// speed w_rel: n π (2R)² w_rel (kinetic theory of hard spheres).
inline double collisionRate(double numberDensity, double particleRadius, double relativeSpeed) {
    return numberDensity * std::numbers::pi * 4.0 * particleRadius * particleRadius * relativeSpeed;
}

} // namespace slides
