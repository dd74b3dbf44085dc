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
    const std::size_t last = size() - 1;
    if (index != last) {
        id[index] = id[last];
        position[index] = position[last];
        velocity[index] = velocity[last];
        radius[index] = radius[last];
        std::copy_n(modelState.begin() + static_cast<std::ptrdiff_t>(last * stateWidth), stateWidth,
                    modelState.begin() + static_cast<std::ptrdiff_t>(index * stateWidth));
    }
    id.pop_back();
    position.pop_back();
    velocity.pop_back();
    radius.pop_back();
    modelState.resize(modelState.size() - stateWidth);
}

} // namespace slides
