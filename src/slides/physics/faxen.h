// Faxén terms of the Maxey–Riley equation: the curvature of the undisturbed flow over the sphere.
//
// Reference: Eq. 3.2 of the reference; Maxey & Riley (1983, Phys. Fluids 26:883, Eq. 6.8);
// Faxén's laws. The drag and the Basset history act on the slip u + (R²/6)∇²u − v (the surface
// average of u over the sphere), the added mass on d/dt(u + (R²/10)∇²u − v) (its volume
// average); the pressure-gradient term m_f DU/Dt keeps the undisturbed acceleration. In the
// step (integrate/maxey_riley.h) the gas velocity the drag and history see is shifted by
// (R²/6)∇²u at both ends, and the added mass gains C_A m_f d/dt((R²/10)∇²u) along the particle's
// path (Maxey & Riley's d/dt), whose integral over the step is the difference of its ends (no
// gradient of ∇²u needed); D/Dt would differ by (u − v)·∇ of it, a product of two small terms.
//
//     physics { faxen on; }   // off by default; needs a carrier with ∇²U (not foamField)
#pragma once

#include "slides/core/vector.h"

namespace slides {

/// u + (R²/6)∇²u: the gas velocity the drag and the history force see [m/s].
inline Vec3 faxenDragVelocity(const Vec3& velocity, const Vec3& velocityLaplacian,
                              double particleRadius) {
    return velocity + particleRadius * particleRadius / 6.0 * velocityLaplacian;
}

/// (R²/10)∇²u: the volume-average correction the added mass sees beside u [m/s].
inline Vec3 faxenAddedMassCorrection(const Vec3& velocityLaplacian, double particleRadius) {
    return particleRadius * particleRadius / 10.0 * velocityLaplacian;
}

} // namespace slides
