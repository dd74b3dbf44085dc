// The adaptive Dormand–Prince step (integrate/adaptive_runge_kutta.h) over a batch of particles
// in a carrier: each particle sub-steps by its own controlled steps until the end of the global
// step, so all arrive there together (frames and collisions see them synchronised); stage by
// stage the carrier is sampled once for every particle still sub-stepping (DESIGN.md: the
// carrier is called per batch, never per particle).
//
// Reference: Section 4.2.3, Eq. 4.18–4.29, Algorithm 2. dv/dt = (u(x) − v)/τ + a with τ the drag
// response time of physics/drag.h at the stage's slip. The carrier is sampled at the global
// step's start time: exact for a carrier frozen over the step.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/vector.h"
#include "slides/physics/drag.h"

#include <span>

namespace slides {

struct AdaptiveSteps {
    long attempted = 0; ///< Dormand–Prince steps tried, all particles
    long rejected = 0;  ///< of them, the ones whose error exceeded the tolerance
};

/// Advances particle i over h[i] (its share of the global step starting at time) by steps
/// controlled by the tolerance.
AdaptiveSteps advanceAdaptiveBatch(std::span<Vec3> position, std::span<Vec3> velocity,
                                   std::span<const double> radius, std::span<const double> h,
                                   double time, double tolerance, const DragParameters& drag,
                                   const Vec3& bodyAcceleration, const CarrierField& carrier);

} // namespace slides
