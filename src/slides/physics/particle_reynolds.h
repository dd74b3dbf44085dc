// The particle Reynolds number Re = 2R|u − v|/ν, on the diameter and the slip speed (Eq. 3.17):
// the one definition that the drag, lift, history and heat-transfer models take.
//
//     const double reynolds = particleReynolds((u - v).norm(), radius, fluid.kinematicViscosity);
#pragma once

#include "slides/core/particle_cloud.h"

namespace slides {

/// Particle Reynolds number on the diameter and the slip speed |u − v|.
inline double particleReynolds(double slipSpeed, double particleRadius, double kinematicViscosity) {
    return particleDiameter(particleRadius) * slipSpeed / kinematicViscosity;
}

} // namespace slides
