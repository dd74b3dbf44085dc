#include "slides/core/particle_order.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace slides {

void orderByLocation(ParticleCloud& cloud, long step) {
    if (step % particleOrderInterval != 0 || cloud.carrierLocation.size() != cloud.size()) return;
    const auto before = [&](std::uint32_t a, std::uint32_t b) {
        const auto la = cloud.carrierLocation[a], lb = cloud.carrierLocation[b];
        return la != lb ? la < lb : cloud.id[a] < cloud.id[b];
    };
    std::vector<std::uint32_t> order(cloud.size());
    std::iota(order.begin(), order.end(), std::uint32_t{0});
    if (std::is_sorted(order.begin(), order.end(), before)) return;
    std::sort(order.begin(), order.end(), before);
    reorderParticles(cloud, order);
}

void reorderParticles(ParticleCloud& cloud, std::span<const std::uint32_t> order) {
    const std::size_t count = cloud.size();
    if (order.size() != count)
        throw std::logic_error("an order of " + std::to_string(order.size()) + " indices for " +
                               std::to_string(count) + " particles");
    ParticleCloud::forEachArray(cloud, [&](const char* name, auto& array) {
        if (array.empty()) return;
        if (array.size() != count)
            throw std::logic_error(std::string("particle array ") + name + " has " +
                                   std::to_string(array.size()) + " entries for " +
                                   std::to_string(count) + " particles");
        reorderParticleArray(array, order);
    });
    if (cloud.stateWidth == 0) return;
    const auto n = static_cast<std::ptrdiff_t>(count);
    const auto width = static_cast<std::ptrdiff_t>(cloud.stateWidth);
    std::vector<double> ordered(cloud.modelState.size());
#pragma omp parallel for schedule(static) if (n >= minimumParallelSweep)
    for (std::ptrdiff_t k = 0; k < n; ++k)
        std::copy_n(cloud.modelState.begin() + order[k] * width, width,
                    ordered.begin() + k * width);
    cloud.modelState.swap(ordered);
}

} // namespace slides
