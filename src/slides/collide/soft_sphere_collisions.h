// SoftSphereCollisions: the soft-sphere (DEM) contacts of the moving particles — Hertz–Mindlin
// loads of every touching pair and of each particle on the soft walls, as the forces and
// torques that the stepper applies in two half kicks around its stream step (velocity Verlet,
// the scheme of LIGGGHTS' nve/sphere).
//
// Reference: Section 2.2 of the reference (Eq. 2.4–2.14; collide/soft_sphere_pair.h), Sec. 4.2.2
// (binning, collide/cell_grid.h); Verlet 1967 neighbour lists with a skin.
// 1. Neighbour list: the pairs of particles closer than R_a + R_b + s, and the particle–wall
//    pairs closer than R + s, with skin s = neighbourSkin × the largest radius. It is rebuilt
//    when the cloud changed (injection, removal) or a particle moved more than s/2 since the
//    last build, so no pair left out can touch. Each entry carries its contact's tangential
//    spring, handed over to the rebuilt list by the particles' ids.
// 2. Loads of the touching entries, and of those that parted in this step under a law that may
//    pull (the dashpot's pull up to the parting, once: partingNormalForce), in parallel (a squared
//    distance tells the apart ones before any root is taken); then each particle in contact sums
//    its entries' loads in the order of its partners' ids. The sum is thus the same for any thread
//    count and any rebuild history, and a pair's equal and opposite forces conserve momentum to
//    round-off. Only particles in contact carry a load, so the half kicks visit only those while
//    the cloud keeps them at their indices (all particles otherwise, skipping zero loads alike).
// With temperatures tracked (physics.heatTransfer, collisions.heating), each contact's dissipated
// power (ContactLoad::dissipatedPower) over the step heats its particles alike (Eq. 2.117); with
// collisions.conduction, touching particles exchange heat through the gap (Eq. 2.118,
// physics/contact_conduction.h) with the temperatures at the step's start (walls do not).
// Soft walls are the surfaces whose interaction is rebound (meetsBySoftContact); absorbing and
// deposit surfaces, and the deposit, keep meeting particles at the touch (surfaces/).
//
//     collisions
//     {
//         model softSphere;
//         restitution { model constant; coefficient 0.9; }   // fixes the damping
//         friction { dynamic 0.3; }                          // the Coulomb limit μ
//         softSphereCoeffs { damping restitution; neighbourSkin 0.2; }
//     }
#pragma once

#include "slides/collide/cell_grid.h"
#include "slides/collide/soft_sphere_pair.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/injection_settings.h"
#include "slides/surfaces/surface_settings.h"

#include <cstdint>
#include <utility>
#include <vector>

namespace slides {

/// The tangential spring of a contact that is touching, by the ids of its bodies (a checkpoint
/// keeps these). A wall is named by wallId(surface).
struct ContactSpring {
    ParticleId first = 0;  ///< the lower id of a pair
    ParticleId second = 0; ///< the other particle, or wallId(surface)
    Vec3 displacement = Vec3::Zero();
    double largestOverlap = 0; ///< δ_max so far [m] (waltonBraun)
};

/// The id that names surface s as the second body of a contact.
constexpr ParticleId wallId(std::size_t surface) { return ~ParticleId{0} - surface; }

class SoftSphereCollisions {
public:
    /// Surface s is a soft wall where meetsBySoftContact(collisions, its interaction). Particles
    /// outside `domain` touch no other: they escape at the step's end.
    SoftSphereCollisions(const CollisionSettings& collisions, const ParticleSettings& particles,
                         const std::vector<Surface>& surfaces, const Box& domain);

    /// Advances every particle's velocity and spin by its contact load over half its step
    /// (cloud.contactForce, contactTorque: sized by the caller, zero for new particles).
    void halfKick(ParticleCloud& cloud, const std::vector<double>& stepLengths) const;

    /// The loads at the particles' current state, stored in cloud.contactForce and
    /// contactTorque; the springs are stretched over the step dt.
    void updateLoads(ParticleCloud& cloud, double dt);

    /// The particles' indices in the order of the contact grid's cells (x slowest; within a
    /// cell, as they are now), then those outside the domain in the order they are: particles
    /// near each other in space, near in memory (core/particle_order.h). Leaves the list as
    /// it is.
    std::vector<std::uint32_t> cellOrder(const ParticleCloud& cloud);

    /// Pair contacts begun so far.
    long collisions() const { return collisions_; }
    /// Contacts with each surface begun in the last updateLoads (zero for surfaces that are not
    /// soft walls): the rebounds off the soft walls.
    const std::vector<std::uint64_t>& newWallContacts() const { return newWallContacts_; }
    /// Neighbour-list builds so far.
    long listBuilds() const { return listBuilds_; }

    /// The springs of the contacts now touching, ordered by ids.
    std::vector<ContactSpring> springs() const;
    /// Continues a checkpointed run: its counts and the springs of its touching contacts.
    void resume(long collisions, std::vector<ContactSpring> springs);

private:
    /// One neighbour: a pair of particles or a particle and a wall.
    struct Entry {
        std::uint32_t first = 0; ///< cloud index; the lower id of a pair
        std::int32_t second = 0; ///< cloud index, or −1 − surface for a wall
        TangentialSpring spring;
        bool touching = false;
        bool parting = false; ///< parted in the last updateLoads, with a load (mayPull)
    };

    bool listIsStale(const ParticleCloud& cloud) const;
    /// The neighbour skin for the cloud's largest radius, and the edge of the grid's cells that
    /// finds the pairs within it [m].
    std::pair<double, double> skinAndCellSize(const ParticleCloud& cloud) const;
    /// Whether loaded_ lists every particle with a load, each still at its index.
    bool loadedInPlace(const ParticleCloud& cloud) const;
    /// Zeroes the loads of the particles that had one, and lists those that have one now.
    void collectLoaded(ParticleCloud& cloud);
    void buildList(const ParticleCloud& cloud);
    /// Orders each particle's entries by partner id, for a sum that does not depend on the
    /// order in which the list was found.
    void indexEntriesByParticle();
    /// The entry's bodies by id (those of the list's build) and its spring.
    ContactSpring springOf(const Entry& entry) const;
    /// The entry's effective pair: the moduli of its kind with the bodies' radii and masses.
    ContactPair pairOf(const Entry& entry, const ParticleCloud& cloud) const;

    CollisionSettings settings_;
    ParticleSettings particles_;
    std::vector<Surface> surfaces_;
    Box domain_;
    SoftContactLaw law_;
    std::vector<std::size_t> softWalls_; ///< surface indices
    /// E*, G*, yield stress and adhesion of two particles, and of a particle on each surface
    /// (radius and mass are the entry's: pairOf).
    /// The moduli of each pair of species (one entry when the particles are alike): entry
    /// S·a + b for species a against b, S species; of each species against each surface: entry
    /// surfaces·a + s.
    std::vector<ContactPair> particleModuli_;
    std::vector<ContactPair> wallModuli_;
    std::size_t speciesCount_ = 1;
    double skin_ = 0; ///< [m] of the current list
    CellGrid grid_;
    std::vector<double> slotRadius_; ///< radii in the grid's cell order, scratch of buildList
    std::vector<Entry> entries_;
    std::vector<ContactLoad> loads_; ///< per entry, written for the touching and parting ones
    std::vector<std::uint32_t> loadedEntries_; ///< touching or parting, ascending (updateLoads)
    /// The particles that the last updateLoads gave a load (ascending cloud indices), with
    /// their ids: every other particle's load is zero, so the kicks visit only these while
    /// the cloud keeps them where they were (kickedByList).
    std::vector<std::uint32_t> loaded_;
    std::vector<ParticleId> loadedIds_;
    bool loadsListed_ = false;           ///< loaded_ holds every particle with a load
    std::vector<std::uint8_t> isLoaded_; ///< per particle, scratch of collectLoaded
    /// entryOf_[entryStart_[i] … entryStart_[i + 1]) are particle i's entries, as 2 e + side
    /// (side 1: the particle is the entry's second body).
    std::vector<std::uint32_t> entryStart_, entryOf_;
    std::vector<ParticleId> builtIds_;
    std::vector<Vec3> builtPositions_;
    std::vector<ContactSpring> pendingSprings_; ///< from resume, handed over at the next build
    long collisions_ = 0;
    long listBuilds_ = 0;
    std::vector<std::uint64_t> newWallContacts_;
};

} // namespace slides
