// The exact drag relaxation step (integrate/integrator.h, relaxExactly with the response time
// of physics/drag.h) over a batch of particles in SIMD lanes: Highway, dispatched at run time to
// the widest instruction set the CPU has (SSE2 … AVX-512), with its vector exp, expm1 and log.
//
// Each particle is one lane and every lane runs the same instructions (a batch's last,
// partial vector is padded), so a particle's result does not depend on where the batch is split
// between threads. The scalar relaxExactly + dragResponseTime stay the reference: Highway's
// expm1 and log are within 4 ulp, and tests/unit/test_vector_kernels.cpp holds the two within
// 1e-13 of each other.
//
//     time { integrator exponentialMidpoint; }   physics { drag haiderLevenspiel; }
#pragma once

#include "slides/core/vector.h"
#include "slides/physics/drag.h"

#include <span>

namespace slides {

/// The particles' state and what their step sees, one entry per particle. The end state may
/// be the start state's arrays (advanced in place), and the slip origin either of them: a
/// vector's lanes are all read before any is written.
struct RelaxationBatch {
    std::span<const Vec3> startPosition; ///< x [m]
    std::span<const Vec3> startVelocity; ///< v [m/s]
    std::span<Vec3> position;            ///< x after the step [m]
    std::span<Vec3> velocity;            ///< v after the step [m/s]
    std::span<const Vec3> gas;           ///< u [m/s]
    std::span<const Vec3> slipOrigin;    ///< w: τ follows from the slip |u − w| [m/s]
    std::span<const double> radius;      ///< [m]
    std::span<const double> stepLength;  ///< h_i [s]
    /// Particles of differing species (integrate/injection_settings.h): each one's density ρp
    /// [kg/m³] and body acceleration a_i [m/s²] in place of the drag's ρp and the common a;
    /// empty when the particles are alike.
    std::span<const double> density = {};
    std::span<const Vec3> acceleration = {};
};

/// relaxExactly(x_i, v_i, u_i, τ(R_i, |u_i − w_i|), a, fraction × h_i) (a_i and ρp,i where the
/// batch gives them) from the start state to
/// the end state of every particle i, in parallel (OpenMP) when the batch is large.
void relaxBatchExactly(const RelaxationBatch& batch, const DragParameters& drag,
                       const Vec3& bodyAcceleration, double fraction);

} // namespace slides
