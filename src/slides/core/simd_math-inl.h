// Vector maths for the SIMD kernels beyond Highway's contrib/math: x^p, and the loop that runs
// a kernel over a batch one full vector at a time, padding the last one.
// Reference: Highway (github.com/google/highway), its per-target "-inl.h" header convention
// (included once per instruction set by hwy/foreach_target.h).
//
// Accuracy: Highway's Exp is within 1 ulp, Log within 4; x^p = e^(p ln x) adds |p ln x| × 4 ulp
// (3e-15 relative at x = 1e3, p = 0.65).

// Per-target include guard (Highway's convention for headers included by foreach_target).
#if defined(SLIDES_CORE_SIMD_MATH_INL_H_) == defined(HWY_TARGET_TOGGLE)
#ifdef SLIDES_CORE_SIMD_MATH_INL_H_
#undef SLIDES_CORE_SIMD_MATH_INL_H_
#else
#define SLIDES_CORE_SIMD_MATH_INL_H_
#endif

#include "slides/core/parallel.h"

#include <hwy/contrib/math/math-inl.h>
#include <hwy/highway.h>

#include <cstddef>

HWY_BEFORE_NAMESPACE();
namespace slides::HWY_NAMESPACE {
namespace hn = hwy::HWY_NAMESPACE;

/// x^p for x ≥ 0 (0 at x = 0, as std::pow).
template <class D, class V> HWY_INLINE V Pow(D d, V x, double p) {
    const V power = hn::Exp(d, hn::Mul(hn::Set(d, p), hn::Log(d, x)));
    return hn::IfThenElseZero(hn::Gt(x, hn::Zero(d)), power);
}

/// Calls block(first) for every full vector of a batch of `count` items, then
/// pad(first, remaining) once for the last, partial one: pad copies the remaining items into
/// a vector's worth of scratch, runs the block there and copies the results back. Every item
/// thus takes the same instructions in its lane, wherever the batch is split between threads;
/// so the vectors can go to the threads in chunks taken as each thread gets free (a core busy
/// elsewhere then holds up no other).
template <class Block, class Pad>
void forEachVector(std::size_t count, std::size_t lanes, Block block, Pad pad) {
    const auto vectors = static_cast<std::ptrdiff_t>(count / lanes);
    constexpr std::ptrdiff_t chunk = 32; // vectors: 128 particles of AVX2, a few µs of work
    const bool parallel = static_cast<std::ptrdiff_t>(count) >= minimumParallelBatch;
#pragma omp parallel for schedule(dynamic, chunk) if (parallel)
    for (std::ptrdiff_t n = 0; n < vectors; ++n) block(static_cast<std::size_t>(n) * lanes);
    const std::size_t done = static_cast<std::size_t>(vectors) * lanes;
    if (done < count) pad(done, count - done);
}

/// The most lanes of doubles any target has (AVX-512: 8).
inline constexpr std::size_t maxDoubleLanes = HWY_MAX_BYTES / sizeof(double);

} // namespace slides::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#endif // per-target include guard
