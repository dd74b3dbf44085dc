#include "slides/physics/drag_response.h"

// Compiled once per instruction set (Highway's foreach_target), dispatched at run time.
#undef HWY_TARGET_INCLUDE
#define HWY_TARGET_INCLUDE "slides/physics/drag_response.cpp"
#include <hwy/foreach_target.h> // IWYU pragma: keep

#include "slides/core/simd_math-inl.h"
#include "slides/physics/drag_response-inl.h"

#include <hwy/highway.h>

#include <array>

HWY_BEFORE_NAMESPACE();
namespace slides::HWY_NAMESPACE {

void DragResponseTimes(const DragParameters& drag, std::span<const double> radius,
                       std::span<const double> slipSpeed, std::span<double> responseTime) {
    const hn::ScalableTag<double> d;
    const auto run = [&](const double* r, const double* s, double* tau) {
        hn::StoreU(ResponseTime(d, drag, hn::LoadU(d, r), hn::LoadU(d, s)), d, tau);
    };
    forEachVector(
        radius.size(), hn::Lanes(d),
        [&](std::size_t first) { run(&radius[first], &slipSpeed[first], &responseTime[first]); },
        [&](std::size_t first, std::size_t count) {
            std::array<double, maxDoubleLanes> r, s, tau;
            for (std::size_t k = 0; k < maxDoubleLanes; ++k) {
                r[k] = radius[first + (k < count ? k : 0)];
                s[k] = slipSpeed[first + (k < count ? k : 0)];
            }
            run(r.data(), s.data(), tau.data());
            for (std::size_t k = 0; k < count; ++k) responseTime[first + k] = tau[k];
        });
}

} // namespace slides::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace slides {

HWY_EXPORT(DragResponseTimes);

void dragResponseTimes(const DragParameters& drag, std::span<const double> radius,
                       std::span<const double> slipSpeed, std::span<double> responseTime) {
    HWY_DYNAMIC_DISPATCH(DragResponseTimes)(drag, radius, slipSpeed, responseTime);
}

} // namespace slides
#endif
