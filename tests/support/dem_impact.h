// One impact of two spheres, or of a sphere on a resting plane wall, integrated with the soft
// contact load of collide/soft_sphere_pair.h by velocity Verlet with rotations (the scheme of
// LIGGGHTS' nve/sphere: half kick, drift, load from the new positions and the half-step
// velocities, half kick), until the bodies have separated or over a fixed time.
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
    Vec3 gravity = Vec3::Zero(); ///< [m/s²]
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

/// Half of a kick: both bodies' velocities and spins advanced by the load and gravity over h.
inline void kick(ImpactScene& scene, const ContactLoad& load, double h) {
    const auto kickBody = [&](DemBody& body, const Vec3& force, const Vec3& torque) {
        body.sphere.velocity += (force / body.mass + scene.gravity) * h;
        body.sphere.spin += torque / body.inertia() * h;
    };
    kickBody(scene.first, load.force, load.torqueOnFirst);
    if (scene.second) kickBody(*scene.second, -load.force, load.torqueOnSecond);
}

/// One velocity Verlet step; load holds the load at the start and is updated to the end.
inline void step(ImpactScene& scene, TangentialSpring& spring, ContactLoad& load, double dt) {
    kick(scene, load, 0.5 * dt);
    scene.first.sphere.position += scene.first.sphere.velocity * dt;
    if (scene.second) scene.second->sphere.position += scene.second->sphere.velocity * dt;
    load = impactLoad(scene, spring, dt);
    kick(scene, load, 0.5 * dt);
}

/// Integrates the scene in place with step dt until the contact has ended.
inline ImpactRecord runImpact(ImpactScene& scene, double dt, long maxSteps = 10'000'000) {
    TangentialSpring spring;
    ImpactRecord record;
    ContactLoad load = impactLoad(scene, spring, dt);
    double previousOverlap = load.overlap;
    if (previousOverlap > 0) throw std::logic_error("runImpact: bodies overlap at the start");
    for (long n = 1; n <= maxSteps; ++n) {
        step(scene, spring, load, dt);
        const double crossing = (n - 1 + previousOverlap / (previousOverlap - load.overlap)) * dt;
        if (previousOverlap <= 0 && load.overlap > 0 && record.contactStart < 0)
            record.contactStart = crossing;
        record.maxOverlap = std::max(record.maxOverlap, load.overlap);
        record.maxForce = std::max(record.maxForce, load.force.norm());
        if (previousOverlap > 0 && load.overlap <= 0) {
            record.contactEnd = crossing;
            record.steps = n;
            kick(scene, load, 0.5 * dt); // the next step's half kick: the rest of a parting load
            return record;
        }
        previousOverlap = load.overlap;
    }
    throw std::runtime_error("runImpact: the bodies did not separate");
}

/// Integrates the scene in place over the given number of steps (an enduring contact).
inline void runSteps(ImpactScene& scene, double dt, long steps) {
    TangentialSpring spring;
    ContactLoad load = impactLoad(scene, spring, dt);
    for (long n = 0; n < steps; ++n) step(scene, spring, load, dt);
}

/// Closing speed of a head-on impact along x: the first body's velocity less the second's.
inline double closingSpeedAlongX(const ImpactScene& scene) {
    return scene.first.sphere.velocity.x() -
           (scene.second ? scene.second->sphere.velocity.x() : 0.0);
}

/// Restitution of a head-on impact along x at step dt, the touch falling at fraction phase of
/// a step: the first sphere is placed 10 + (1 − phase) drifts from the wall or the second
/// sphere's surface, which lie at x = 0 (the scenes of chung_ooi.h).
inline double restitutionAtPhase(ImpactScene scene, double dt, double phase) {
    const double approach = closingSpeedAlongX(scene);
    scene.first.sphere.position.x() = -scene.first.sphere.radius - (11 - phase) * approach * dt;
    runImpact(scene, dt);
    return -closingSpeedAlongX(scene) / approach;
}

/// The largest |e_out/e − 1| over sixteen phases of the touch within a step of dt.
inline double worstRestitutionError(const ImpactScene& scene, double dt, double restitution) {
    double worst = 0;
    for (int k = 0; k < 16; ++k)
        worst = std::max(worst,
                         std::abs(restitutionAtPhase(scene, dt, (k + 0.5) / 16) / restitution - 1));
    return worst;
}

} // namespace slides::test
