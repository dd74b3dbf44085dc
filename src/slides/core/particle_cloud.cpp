#include "slides/core/particle_cloud.h"

namespace slides {

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
    forEachArray(*this, [index](const char*, auto& array) {
        if (array.empty()) return;
        array[index] = array.back();
        array.pop_back();
    });
}

} // namespace slides
