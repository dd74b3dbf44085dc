// Time integrators for the particle equation of motion dv/dt = (u − v)/τ + a, dx/dt = v.
//
// τ = τ_St / f(Re) is the drag response time (physics/drag.h), a the body acceleration
// (physics/body_force.h), u the gas velocity at the particle. The exponential schemes integrate
// the drag relaxation exactly for u, τ and a frozen over the step (exponential time
// differencing, Cox & Matthews 2002), so τ ≪ dt stays stable and the velocity relaxes to
// u + τa instead of oscillating. explicitEuler is kept for comparison; it is unstable for
// dt > 2τ. adaptiveRungeKutta sub-steps each particle within the step by Dormand–Prince steps
// controlled by time.tolerance (Section 4.2.3, Eq. 4.18–4.29; integrate/adaptive_runge_kutta.h),
// for gas that varies strongly along a step, where freezing u over it is not accurate enough.
//
//     time { integrator exponentialMidpoint; }  // explicitEuler | exponentialEuler |
//     exponentialMidpoint | adaptiveRungeKutta (with tolerance 1e-6;)
//
// How to add one: an enumerator, its name and order in integratorNames(), and its branch in
// the stepper (run/stepper.cpp); tests/verification/test_integrators.cpp measures its order.
#pragma once

#include "slides/core/vector.h"

#include <array>
#include <cmath>
#include <string_view>

namespace slides {

enum class Integrator { explicitEuler, exponentialEuler, exponentialMidpoint, adaptiveRungeKutta };

struct IntegratorName {
    Integrator value;
    std::string_view name;
    int order; ///< design order of accuracy for smooth u(x) and τ(v), fixed steps
};

constexpr std::array<IntegratorName, 4> integratorNames() {
    return {{{Integrator::explicitEuler, "explicitEuler", 1},
             {Integrator::exponentialEuler, "exponentialEuler", 1},
             {Integrator::exponentialMidpoint, "exponentialMidpoint", 2},
             {Integrator::adaptiveRungeKutta, "adaptiveRungeKutta", 5}}};
}

/// Advances (x, v) over h by the exact solution of dv/dt = (u − v)/τ + a, dx/dt = v with
/// u, τ, a constant:  v(h) = w + (v − w) e^(−h/τ),  x(h) = x + w h + (v − w) τ (1 − e^(−h/τ)),
/// with w = u + τa the terminal velocity. expm1 keeps both exact for h ≪ τ and h ≫ τ.
inline void relaxExactly(Vec3& position, Vec3& velocity, const Vec3& gasVelocity,
                         double responseTime, const Vec3& bodyAcceleration, double h) {
    const Vec3 terminal = gasVelocity + responseTime * bodyAcceleration;
    const double decayed = -std::expm1(-h / responseTime); // 1 − e^(−h/τ)
    const Vec3 excess = velocity - terminal;
    position += terminal * h + excess * (responseTime * decayed);
    velocity = terminal + excess * (1.0 - decayed);
}

/// dv/dt = (u − v)/τ + a: drag and the body acceleration (the explicit schemes' right-hand side).
inline Vec3 particleAcceleration(const Vec3& gasVelocity, const Vec3& velocity, double responseTime,
                                 const Vec3& bodyAcceleration) {
    return (gasVelocity - velocity) / responseTime + bodyAcceleration;
}

/// One forward-Euler step of the same equations.
inline void advanceExplicitly(Vec3& position, Vec3& velocity, const Vec3& gasVelocity,
                              double responseTime, const Vec3& bodyAcceleration, double h) {
    position += velocity * h;
    velocity += particleAcceleration(gasVelocity, velocity, responseTime, bodyAcceleration) * h;
}

} // namespace slides
