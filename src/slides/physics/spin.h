// Particle spin: the viscous torque on a rotating sphere (Eq. 3.18), relaxing ω to half the
// fluid vorticity.
//
// Reference: Eq. 3.18 of the reference, T = −8πμR³ω (Rubinow & Keller 1961, J. Fluid Mech.
// 11:447; Happel & Brenner), applied to the spin relative to the local fluid rotation ½∇×U.
// With I = (2/5) m_p R² the spin relaxes with τ_ω = I/(8πμR³) = ρp R² / (15 ρf ν):
//   dω/dt = (½∇×U − ω)/τ_ω,  ω(t) = ½∇×U + (ω0 − ½∇×U) e^{−t/τ_ω} for frozen ∇U.
// The unsteady extension Eq. 3.19 (Feuillebois & Lasek 1978) is not implemented.
//
//     physics { spin on; }   // off by default; Magnus lift needs it
#pragma once

#include "slides/core/vector.h"

#include <cmath>

namespace slides {

/// τ_ω = I / (8πμR³) = ρp R² / (15 ρf ν) [s] (Eq. 3.18).
inline double spinResponseTime(double particleDensity, double fluidDensity,
                               double kinematicViscosity, double particleRadius) {
    return particleDensity * particleRadius * particleRadius /
           (15.0 * fluidDensity * kinematicViscosity);
}

/// Advances ω over h exactly for a frozen fluid rotation ½∇×U.
inline Vec3 relaxSpin(const Vec3& spin, const Vec3& fluidVorticity, double responseTime, double h) {
    const Vec3 fluidRotation = 0.5 * fluidVorticity;
    return fluidRotation + (spin - fluidRotation) * std::exp(-h / responseTime);
}

} // namespace slides
