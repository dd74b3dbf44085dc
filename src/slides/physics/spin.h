// Particle spin: the viscous torque on a rotating sphere (Eq. 3.18), relaxing ω to half the
// fluid vorticity.
//
// Reference: Eq. 3.18 of the reference, T = −8πμR³ω (Rubinow & Keller 1961, J. Fluid Mech.
// 11:447; Happel & Brenner), applied to the spin relative to the local fluid rotation ½∇×U.
// With I = (2/5) m_p R² the spin relaxes with τ_ω = I/(8πμR³) = ρp R² / (15 ρf ν):
//   dω/dt = (½∇×U − ω)/τ_ω,  ω(t) = ½∇×U + (ω0 − ½∇×U) e^{−t/τ_ω} for frozen ∇U.
// The unsteady extension Eq. 3.19 (Feuillebois & Lasek 1978, Q. J. Mech. Appl. Math. 31:435)
// adds the history of σ = ½∇×U − ω with t_v = R²/ν:
//   dω/dt = [σ + (t_v/3) d/dt ∫ g(t − τ) σ dτ]/τ_ω,  g = (1/√t_v)[1/√(πℓ) − ψ(ℓ/t_v)/√t_v],
// ψ(U) = e^U erfc(√U): in the form r_H d/dt ∫ k σ of physics/history_integrator.h, k = 1/√ℓ −
// √(π/t_v) ψ(ℓ/t_v) and r_H below. A sphere released with σ ≠ 0 meets the fluid at rest.
//
//     physics { spin on; spinHistory off; }   // off by default; Magnus lift needs spin
#pragma once

#include "slides/core/vector.h"

#include <cmath>
#include <numbers>

namespace slides {

/// τ_ω = I / (8πμR³) = ρp R² / (15 ρf ν) [s] (Eq. 3.18).
inline double spinResponseTime(double particleDensity, double fluidDensity,
                               double kinematicViscosity, double particleRadius) {
    return particleDensity * particleRadius * particleRadius /
           (15.0 * fluidDensity * kinematicViscosity);
}

/// r_H = √t_v/(3√π τ_ω) [1/√s] of the spin's history term (Eq. 3.19), t_v = R²/ν.
inline double spinHistoryRate(double responseTime, double viscousTime) {
    return std::sqrt(viscousTime / std::numbers::pi) / (3.0 * responseTime);
}

/// Advances ω over h exactly for a frozen fluid rotation ½∇×U.
inline Vec3 relaxSpin(const Vec3& spin, const Vec3& fluidVorticity, double responseTime, double h) {
    const Vec3 fluidRotation = 0.5 * fluidVorticity;
    return fluidRotation + (spin - fluidRotation) * std::exp(-h / responseTime);
}

} // namespace slides
