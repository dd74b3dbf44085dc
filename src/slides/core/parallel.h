// Parallel loops over particles: OpenMP, each particle's update independent of the others, so
// results do not depend on the thread count. A batch smaller than minimumParallelBatch runs on
// the calling thread: waking threads costs more than a few particles' work (a carrier sampled
// at one point, a pilot of a hundred particles).
//
//     #pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
#pragma once

#include <cstddef>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

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

/// What collect(i, out) appends to out for i = 0 … count − 1, in that order, gathered on the
/// threads from parallelFrom items (static blocks, joined in thread order): the same list on any
/// thread count.
template <typename T, typename Collect>
std::vector<T> collectInOrder(std::ptrdiff_t count, Collect collect,
                              std::ptrdiff_t parallelFrom = minimumParallelBatch) {
    std::vector<std::vector<T>> perThread(1);
#pragma omp parallel if (count >= parallelFrom)
    {
#ifdef _OPENMP
#pragma omp single
        perThread.resize(static_cast<std::size_t>(omp_get_num_threads()));
        std::vector<T>& mine = perThread[static_cast<std::size_t>(omp_get_thread_num())];
#else
        std::vector<T>& mine = perThread[0];
#endif
#pragma omp for schedule(static)
        for (std::ptrdiff_t i = 0; i < count; ++i) collect(i, mine);
    }
    std::vector<T> all = std::move(perThread[0]);
    for (std::size_t t = 1; t < perThread.size(); ++t)
        all.insert(all.end(), perThread[t].begin(), perThread[t].end());
    return all;
}

} // namespace slides
