// ParticleCollisions: the collide step between moving particles, after the stream step moved
// them (collide-and-stream, Section 4.2.2 of the reference).
//
// 1. Broad phase: the midpoints of the step's chords are binned in a hashed cell grid
//    (collide/cell_grid.h) with cells of edge 2 R_max + d_max (d_max the longest chord), so
//    that any two particles that touched during the step lie in the same or adjacent cells.
// 2. Narrow phase, in parallel: each candidate pair's first touch along the chords
//    (collide/swept_contact.h).
// 3. Contacts are resolved one after another in the order of their touch (ties by particle
//    id), each by the impulse law (collide/impulse.h): every impulse conserves momentum
//    exactly, a particle in several contacts sees the earlier ones, and the order is the same
//    for any thread count. A particle's velocity change Δv also moves it by (1 − s) h Δv, the
//    rest of the step flown with the new velocity. With temperatures tracked, the energy each
//    contact dissipates heats both particles alike (Eq. 2.117, collisionalTemperatureRise).
//
//     collisions { model impulse; restitution { model velocityDependent; } }
#pragma once

#include "slides/collide/cell_grid.h"
#include "slides/collide/collision_settings.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/injection_settings.h"

#include <cstdint>
#include <vector>

namespace slides {

/// Two particles (cloud indices) that touch at fraction `fraction` of the step.
struct ParticleContact {
    std::uint32_t a = 0, b = 0;
    double fraction = 0;
};

class ParticleCollisions {
public:
    /// The particles' density, material and specific heat set their masses, contact and heating.
    ParticleCollisions(const CollisionSettings& collisions, const ParticleSettings& particles);

    /// Resolves the contacts of the step that moved each particle i from startPositions[i] to
    /// cloud.position[i] over stepLengths[i].
    void collide(ParticleCloud& cloud, const std::vector<Vec3>& startPositions,
                 const std::vector<double>& stepLengths);

    /// Contacts resolved so far (pairs that exchanged an impulse).
    long collisions() const { return collisions_; }
    /// Continues the count of a checkpointed run.
    void resume(long collisions) { collisions_ = collisions; }

private:
    void findContacts(const ParticleCloud& cloud, const std::vector<Vec3>& startPositions);

    CollisionSettings settings_;
    ParticleSettings particles_;
    CellGrid grid_;
    std::vector<Vec3> midpoints_; ///< of the step's chords, binned
    std::vector<ParticleContact> contacts_;
    long collisions_ = 0;
};

} // namespace slides
