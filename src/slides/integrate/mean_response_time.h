// The Stokes response time of a run's particles at their mean radius, τ_St = 2 ρp R̄² / (9 ρf ν)
// (Eq. 3.16, physics/drag.h stokesResponseTime; R̄ = RadiusDistribution::meanRadius()): the one
// response time the run's report and summary.json quote.
#pragma once

#include "slides/carrier/carrier_settings.h"
#include "slides/integrate/injection_settings.h"
#include "slides/physics/drag.h"

namespace slides {

inline double meanStokesResponseTime(const ParticleSettings& particles,
                                     const FluidSettings& fluid) {
    return stokesResponseTime(particles.density, particles.radius.meanRadius(), fluid.density,
                              fluid.kinematicViscosity);
}

} // namespace slides
