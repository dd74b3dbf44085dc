// Parallel loops over particles: OpenMP, each particle's update independent of the others, so
// results do not depend on the thread count. A batch smaller than minimumParallelBatch runs on
// the calling thread: waking threads costs more than a few particles' work (a carrier sampled
// at one point, a pilot of a hundred particles).
//
//     #pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
#pragma once

#include <cstddef>

namespace slides {

inline constexpr std::ptrdiff_t minimumParallelBatch = 256;

} // namespace slides
