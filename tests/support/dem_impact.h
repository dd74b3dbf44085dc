// One impact of two spheres, or of a sphere on a resting plane wall, integrated with the soft
// contact load of collide/soft_sphere_pair.h by velocity Verlet with rotations (the scheme of
// LIGGGHTS' nve/sphere: half kick, drift, load from the new positions and the half-step
// velocities, half kick), until the bodies have separated.
#pragma once

#include "slides/collide/soft_sphere_pair.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

namespace slides::test {

struct DemBody {
    ContactSphere sphere;
    double mass = 0; ///< [kg]
    double inertia() const { return 0.4 * mass * sphere.radius * sphere.radius; }
    Vec3 momentum() const { return mass * sphere.velocity; }
    /// Angular momentum about the origin: orbital plus spin.
    Vec3 angularMomentum() const {
        return sphere.position.cross(momentum()) + inertia() * sphere.spin;
    }
    double kineticEnergy() const {
        return 0.5 * mass * sphere.velocity.squaredNorm() +
               0.5 * inertia() * sphere.spin.squaredNorm();
    }
};

/// A sphere (first) against a second sphere or, when second is empty, a plane wall.
struct ImpactScene {
    ContactPair pair;
    SoftContactLaw law;
    DemBody first;
    std::optional<DemBody> second;
    Vec3 wallPoint = Vec3::Zero();
    Vec3 wallNormal = Vec3::UnitX();
};

struct ImpactRecord {
    double contactStart = -1; ///< [s], where the overlap crosses 0 (linear between steps)
    double contactEnd = -1;   ///< [s]
    double maxOverlap = 0;    ///< [m], largest over the steps
    double maxForce = 0;      ///< [N], largest |force| over the steps
    long steps = 0;
    double duration() const { return contactEnd - contactStart; }
};

inline ContactLoad impactLoad(const ImpactScene& scene, TangentialSpring& spring, double dt) {
    if (scene.second)
        return sphereSphereLoad(scene.pair, scene.law, scene.first.sphere, scene.second->sphere,
                                spring, dt);
    return sphereWallLoad(scene.pair, scene.law, scene.first.sphere, scene.wallPoint,
                          scene.wallNormal, spring, dt);
}

inline void kick(DemBody& body, const Vec3& force, const Vec3& torque, double h) {
    body.sphere.velocity += force / body.mass * h;
    body.sphere.spin += torque / body.inertia() * h;
}

/// Integrates the scene in place with step dt until the contact has ended.
inline ImpactRecord runImpact(ImpactScene& scene, double dt, long maxSteps = 10'000'000) {
    TangentialSpring spring;
    ImpactRecord record;
    ContactLoad load = impactLoad(scene, spring, dt);
    double previousOverlap = load.overlap;
    if (previousOverlap > 0) throw std::logic_error("runImpact: bodies overlap at the start");
    for (long step = 1; step <= maxSteps; ++step) {
        kick(scene.first, load.force, load.torqueOnFirst, 0.5 * dt);
        if (scene.second) kick(*scene.second, -load.force, load.torqueOnSecond, 0.5 * dt);
        scene.first.sphere.position += scene.first.sphere.velocity * dt;
        if (scene.second) scene.second->sphere.position += scene.second->sphere.velocity * dt;
        load = impactLoad(scene, spring, dt);
        kick(scene.first, load.force, load.torqueOnFirst, 0.5 * dt);
        if (scene.second) kick(*scene.second, -load.force, load.torqueOnSecond, 0.5 * dt);

        const double crossing =
            (step - 1 + previousOverlap / (previousOverlap - load.overlap)) * dt;
        if (previousOverlap <= 0 && load.overlap > 0 && record.contactStart < 0)
            record.contactStart = crossing;
        record.maxOverlap = std::max(record.maxOverlap, load.overlap);
        record.maxForce = std::max(record.maxForce, load.force.norm());
        if (previousOverlap > 0 && load.overlap <= 0) {
            record.contactEnd = crossing;
            record.steps = step;
            return record;
        }
        previousOverlap = load.overlap;
    }
    throw std::runtime_error("runImpact: the bodies did not separate");
}

} // namespace slides::test
