// The adaptive Dormand–Prince step (integrate/adaptive_runge_kutta.h) over a batch of particles
// in a carrier: each particle sub-steps by its own controlled steps until the end of the global
// step, so all arrive there together (frames and collisions see them synchronised); stage by
// stage the carrier is sampled once for every particle still sub-stepping (DESIGN.md: the
// carrier is called per batch, never per particle), the first stage only where the last stage
// of an accepted sub-step has not given it (first same as last). A particle's path does not depend
// on the other particles of its batch, so a cloud may be split into batches on several threads.
//
// Reference: Section 4.2.3, Eq. 4.18–4.29, Algorithm 2. dv/dt = (u(x) + u' − v)/τ + a
// (integrate/integrator.h particleAcceleration) with τ the drag response time of physics/drag.h
// at the stage's slip (of the particle's own density, and a its own, where species differ) and u'
// a particle's eddy fluctuation, held over the global step
// (integrate/turbulent_dispersion.h); on a charged particle the Lorentz force of Eq. 2.93 adds
// qE/m + v × qB/m (physics/electromagnetic.h). The carrier is sampled at one time for the whole
// batch (the stepper takes the global step's middle): exact for a carrier frozen over the step.
//
//     time { integrator adaptiveRungeKutta; tolerance 1e-6; }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/vector.h"
#include "slides/integrate/adaptive_steps.h"
#include "slides/physics/drag.h"
#include "slides/physics/electromagnetic.h"

#include <cstdint>
#include <span>

namespace slides {

/// The particles of a batch, one entry a particle in every span.
struct AdaptiveBatch {
    std::span<Vec3> position;           ///< x [m], advanced in place
    std::span<Vec3> velocity;           ///< v [m/s], advanced in place
    std::span<const double> radius;     ///< [m]
    std::span<const double> stepLength; ///< h_i, the particle's share of the global step [s]
    /// [s] in: the first sub-step to try, ≤ 0 for h_i; out: the next one (the last accepted
    /// sub-step's proposal), for the particle's next global step. Empty: every particle
    /// starts from h_i.
    std::span<double> trialStep = {};
    std::span<const Vec3> eddyVelocity = {};    ///< u' [m/s]; empty: none
    std::span<const LorentzRates> lorentz = {}; ///< qE/m and qB/m; empty: no charges
    /// Particles of differing species (integrate/injection_settings.h): each one's density ρp
    /// [kg/m³] and body acceleration a_i [m/s²] in place of the drag's ρp and the common a;
    /// empty when the particles are alike.
    std::span<const double> density = {};
    std::span<const Vec3> acceleration = {};
    /// The carrier's cells, if it keeps them: in, at x; out, at the end of the step.
    std::span<std::int32_t> locations = {};
};

/// Advances particle i of the batch over its h_i by steps controlled by the tolerance, the
/// carrier sampled at time.
AdaptiveSteps advanceAdaptiveBatch(const AdaptiveBatch& batch, double time, double tolerance,
                                   const DragParameters& drag, const Vec3& bodyAcceleration,
                                   const CarrierField& carrier);

} // namespace slides
