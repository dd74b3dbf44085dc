#include "slides/core/particle_order.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <string>

namespace slides {

void orderByLocation(ParticleCloud& cloud, long step) {
    if (step % particleOrderInterval != 0 || cloud.carrierLocation.size() != cloud.size()) return;
    const std::size_t count = cloud.size();
    const auto before = [&](std::size_t a, std::size_t b) {
        const auto la = cloud.carrierLocation[a], lb = cloud.carrierLocation[b];
        return la != lb ? la < lb : cloud.id[a] < cloud.id[b];
    };
    std::vector<std::size_t> order(count);
    std::iota(order.begin(), order.end(), std::size_t{0});
    if (std::is_sorted(order.begin(), order.end(), before)) return;
    std::sort(order.begin(), order.end(), before);
    ParticleCloud::forEachArray(cloud, [&](const char* name, auto& array) {
        if (array.empty()) return;
        if (array.size() != count)
            throw std::logic_error(std::string("particle array ") + name + " has " +
                                   std::to_string(array.size()) + " entries for " +
                                   std::to_string(count) + " particles");
        std::remove_reference_t<decltype(array)> ordered(count);
        for (std::size_t k = 0; k < count; ++k) ordered[k] = array[order[k]];
        array.swap(ordered);
    });
    if (cloud.stateWidth == 0) return;
    std::vector<double> ordered(cloud.modelState.size());
    for (std::size_t k = 0; k < count; ++k)
        std::copy_n(
            cloud.modelState.begin() + static_cast<std::ptrdiff_t>(order[k] * cloud.stateWidth),
            cloud.stateWidth, ordered.begin() + static_cast<std::ptrdiff_t>(k * cloud.stateWidth));
    cloud.modelState.swap(ordered);
}

} // namespace slides
