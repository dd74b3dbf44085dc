// The eddy-interaction step (physics/dispersion.h, eddyInteractionStep; Gosman & Ioannides
// 1983) over a batch of particles in SIMD lanes: Highway, dispatched at run time.
//
// The common step, in which the particle stays in its eddy for the whole step (the eddy's
// lifetime and crossing length both last past it), is taken in the lanes: ū' = σξ, and the
// lifetime and length left shrink by h and by the path relative to the eddy gas. A particle
// whose eddy ends or begins inside the step, or whose gas is laminar or not finite there, takes
// the scalar eddyInteractionStep, which stays the reference; only it draws random numbers, from
// the same streams (seed, particle id, eddy counter). Which path a particle takes and what it
// gets depend on that particle alone, so results do not depend on the batch's split or the
// thread count. The lanes agree with the scalar step to 1e-13 (its expm1 and the drag law's pow
// within a few ulp; tests/unit/test_vector_kernels.cpp).
//
//     physics { dispersion { model eddyInteraction; } }
#pragma once

#include "slides/core/eddy_state.h"
#include "slides/core/particle_cloud.h"
#include "slides/physics/dispersion.h"
#include "slides/physics/drag.h"

#include <cstdint>
#include <span>

namespace slides {

/// The particles' eddy states and what their step sees, one entry per particle.
struct EddyBatch {
    std::span<EddyState> eddy;                      ///< advanced over the step
    std::span<const ParticleId> id;                 ///< keys the random streams
    std::span<const Vec3> velocity;                 ///< v at the step's start [m/s]
    std::span<const Vec3> gas;                      ///< U [m/s]
    std::span<const double> turbulentKineticEnergy; ///< k [m²/s²]
    std::span<const double> dissipationRate;        ///< ε [m²/s³]
    std::span<const double> radius;                 ///< [m]
    std::span<const double> stepLength;             ///< h_i [s]
    std::span<Vec3> fluctuation;                    ///< ū' over the step (result) [m/s]
    /// Particles of differing species (integrate/injection_settings.h): each one's density ρp
    /// [kg/m³] and body acceleration a_i [m/s²] in place of the drag's ρp and the common a;
    /// empty when the particles are alike.
    std::span<const double> density = {};
    std::span<const Vec3> acceleration = {};
};

/// eddyInteractionStep of every particle i, with τ(R_i, |v_i − U_i|) and the body acceleration
/// (ρp,i and a_i where the batch gives them), in parallel (OpenMP) when the batch is large;
/// seed: injection.seed.
void eddyInteractionBatch(const EddyBatch& batch, const DispersionConstants& constants,
                          const DragParameters& drag, const Vec3& bodyAcceleration,
                          std::uint64_t seed);

} // namespace slides
