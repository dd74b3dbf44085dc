// Gravity and buoyancy per unit particle mass: (1 − ρf/ρp)·g, the (m − mf)g term of Eq. 3.16.
//
//     physics { gravity (0 -9.81 0); buoyancy on; }
#pragma once

#include "slides/core/vector.h"

namespace slides {

/// Body acceleration of a particle of density ρp in a fluid of density ρf [m/s²].
inline Vec3 bodyAcceleration(const Vec3& gravity, double particleDensity, double fluidDensity,
                             bool buoyancy) {
    return buoyancy ? Vec3((1.0 - fluidDensity / particleDensity) * gravity) : gravity;
}

} // namespace slides
