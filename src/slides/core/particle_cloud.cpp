#include "slides/core/particle_cloud.h"

namespace slides {

namespace {

/// Moves the last entry of a model-state array into index, if the model is on.
template <typename T> void removeModelState(std::vector<T>& state, std::size_t index) {
    if (state.empty()) return;
    state[index] = state.back();
    state.pop_back();
}

} // namespace

void ParticleCloud::reserve(std::size_t count) {
    id.reserve(count);
    position.reserve(count);
    velocity.reserve(count);
    radius.reserve(count);
}

void ParticleCloud::add(ParticleId particleId, const Vec3& x, const Vec3& v,
                        double particleRadius) {
    id.push_back(particleId);
    position.push_back(x);
    velocity.push_back(v);
    radius.push_back(particleRadius);
}

void ParticleCloud::removeAt(std::size_t index) {
    const std::size_t last = size() - 1;
    if (index != last) {
        id[index] = id[last];
        position[index] = position[last];
        velocity[index] = velocity[last];
        radius[index] = radius[last];
    }
    id.pop_back();
    position.pop_back();
    velocity.pop_back();
    radius.pop_back();
    removeModelState(eddy, index);
    removeModelState(temperature, index);
}

} // namespace slides
