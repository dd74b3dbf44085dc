// Arrival: a particle that reached a surface, frozen where and when it touched.
#pragma once

#include "slides/core/particle_cloud.h"

namespace slides {

struct Arrival {
    ParticleId id = 0;
    int surface = 0;                     ///< index into Scene::surfaces
    double time = 0;                     ///< [s]
    Vec3 position;                       ///< centre at first touch [m]
    Vec3 velocity;                       ///< impact velocity [m/s]
    double radius = 0;                   ///< [m]
    double temperature = 0;              ///< [K] at the touch; 0 without heat transfer
    Vec3 angularVelocity = Vec3::Zero(); ///< ω [rad/s] at the touch; zero where ω is not kept
};

} // namespace slides
