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
                       std::span<const double> slipSpeed, std::span<double> responseTime,
                       std::span<const double> density) {
    const hn::ScalableTag<double> d;
    const auto run = [&](const double* r, const double* s, const double* rho, double* tau) {
        const auto lanes =
            rho ? ResponseTime(d, drag, hn::LoadU(d, r), hn::LoadU(d, s), hn::LoadU(d, rho))
                : ResponseTime(d, drag, hn::LoadU(d, r), hn::LoadU(d, s));
        hn::StoreU(lanes, d, tau);
    };
    const bool own = !density.empty();
    forEachVector(
        radius.size(), hn::Lanes(d),
        [&](std::size_t first) {
            run(&radius[first], &slipSpeed[first], own ? &density[first] : nullptr,
                &responseTime[first]);
        },
        [&](std::size_t first, std::size_t count) {
            std::array<double, maxDoubleLanes> r, s, rho, tau;
            for (std::size_t k = 0; k < maxDoubleLanes; ++k) {
                const std::size_t i = first + (k < count ? k : 0);
                r[k] = radius[i];
                s[k] = slipSpeed[i];
                rho[k] = own ? density[i] : 0.0;
            }
            run(r.data(), s.data(), own ? rho.data() : nullptr, tau.data());
            for (std::size_t k = 0; k < count; ++k) responseTime[first + k] = tau[k];
        });
}

} // namespace slides::HWY_NAMESPACE
HWY_AFTER_NAMESPACE();

#if HWY_ONCE
namespace slides {

HWY_EXPORT(DragResponseTimes);

void dragResponseTimes(const DragParameters& drag, std::span<const double> radius,
                       std::span<const double> slipSpeed, std::span<double> responseTime,
                       std::span<const double> density) {
    HWY_DYNAMIC_DISPATCH(DragResponseTimes)(drag, radius, slipSpeed, responseTime, density);
}

} // namespace slides
#endif
