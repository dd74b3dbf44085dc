// Parallel loops over particles: OpenMP, each particle's update independent of the others, so
// results do not depend on the thread count. A batch smaller than minimumParallelBatch runs on
// the calling thread: waking threads costs more than a few particles' work (a carrier sampled
// at one point, a pilot of a hundred particles).
//
//     #pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
#pragma once

#include <cstddef>
#include <vector>

namespace slides {

inline constexpr std::ptrdiff_t minimumParallelBatch = 256;

/// The same for a sweep of a few nanoseconds a particle (a copy, a test of its state): waking a
/// sleeping thread (core/thread_waits.h) costs tens of microseconds, the work of about 10⁴
/// such particles.
inline constexpr std::ptrdiff_t minimumParallelSweep = 1 << 15;

/// to = from, element by element on the threads (a copy of a cloud's array each step is bound
/// by memory bandwidth, which one core does not saturate).
template <typename T> void copyInParallel(const std::vector<T>& from, std::vector<T>& to) {
    const auto count = static_cast<std::ptrdiff_t>(from.size());
    to.resize(from.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelSweep)
    for (std::ptrdiff_t i = 0; i < count; ++i) to[i] = from[i];
}

/// to = count copies of value, on the threads.
template <typename T> void fillInParallel(std::vector<T>& to, std::size_t count, const T& value) {
    to.resize(count);
    const auto n = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static) if (n >= minimumParallelSweep)
    for (std::ptrdiff_t i = 0; i < n; ++i) to[i] = value;
}

} // namespace slides
