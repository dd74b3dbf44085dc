// The drag response time τ = τ_St / f(Re) of physics/drag.h (dragResponseTime, Eq. 3.16–3.17)
// over a batch of particles in SIMD lanes (physics/drag_response-inl.h): Highway, dispatched at
// run time. Each particle is one lane, the last partial vector padded, so a particle's τ does
// not depend on the batch's split or the thread count; within 1e-13 of the scalar
// dragResponseTime, which stays the reference (tests/unit/test_vector_kernels.cpp).
//
//     physics { drag haiderLevenspiel; }
#pragma once

#include "slides/physics/drag.h"

#include <span>

namespace slides {

/// responseTime[i] = dragResponseTime(drag, radius[i], slipSpeed[i]), in parallel (OpenMP) when
/// the batch is large; with density given, particle i's own ρp = density[i] (particle species,
/// integrate/injection_settings.h) in place of drag.particleDensity, to the same bits as a batch
/// of that density alone.
void dragResponseTimes(const DragParameters& drag, std::span<const double> radius,
                       std::span<const double> slipSpeed, std::span<double> responseTime,
                       std::span<const double> density = {});

} // namespace slides
