// Overlaps among injected particles, for the tests of overlap-free injection.
#pragma once

#include "slides/core/particle_cloud.h"

#include <cstddef>

namespace slides::test {

/// How many of the particles from index `first` on overlap a particle before them in the cloud.
inline long overlappingNewcomers(const ParticleCloud& cloud, std::size_t first) {
    long overlapping = 0;
    for (std::size_t i = first; i < cloud.size(); ++i)
        for (std::size_t j = 0; j < i; ++j) {
            const double contact = cloud.radius[i] + cloud.radius[j];
            if ((cloud.position[i] - cloud.position[j]).squaredNorm() < contact * contact) {
                ++overlapping;
                break;
            }
        }
    return overlapping;
}

} // namespace slides::test
