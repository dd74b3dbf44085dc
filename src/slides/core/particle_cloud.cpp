#include "slides/core/particle_cloud.h"

#include <algorithm>

namespace slides {

void ParticleCloud::reserve(std::size_t count) {
    id.reserve(count);
    position.reserve(count);
    velocity.reserve(count);
    radius.reserve(count);
    modelState.reserve(count * stateWidth);
}

void ParticleCloud::add(ParticleId particleId, const Vec3& x, const Vec3& v,
                        double particleRadius) {
    id.push_back(particleId);
    position.push_back(x);
    velocity.push_back(v);
    radius.push_back(particleRadius);
    modelState.resize(modelState.size() + stateWidth, 0.0);
}

void ParticleCloud::removeAt(std::size_t index) {
    forEachArray(*this, [index](const char*, auto& array) {
        if (array.empty()) return;
        array[index] = array.back();
        array.pop_back();
    });
    const std::size_t last = modelState.size() / std::max<std::size_t>(stateWidth, 1);
    if (stateWidth > 0 && index + 1 != last)
        std::copy_n(modelState.begin() + static_cast<std::ptrdiff_t>((last - 1) * stateWidth),
                    stateWidth,
                    modelState.begin() + static_cast<std::ptrdiff_t>(index * stateWidth));
    modelState.resize(modelState.size() - stateWidth);
}

} // namespace slides
