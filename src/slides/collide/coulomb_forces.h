// CoulombForces: the truncated Coulomb force on every charged particle (physics/coulomb.h), summed
// over its partners closer than the cut-off through the broad phase's cell grid, and the half
// kicks by which the stepper applies it around its stream step.
//
// Reference: Eq. 2.94 with the truncation of Eq. 2.97 (Section 2.7.1); Sec. 4.2.2 (binning,
// collide/cell_grid.h). The grid's cells have the cut-off as edge, so every pair closer than it
// is among the grid's pairs, each once. Each particle sums its pairs' forces in the order of its
// partners' ids: the sum is the same for any thread count, cloud order or restart, and a pair's
// equal and opposite forces conserve momentum to round-off.
// In the step (run/stepper.h), as the soft-sphere contacts: a half kick v += F h/(2m) with the
// force at the step's start, the stream step, the force anew at the end and a second half kick —
// velocity Verlet, second order and symplectic without gas (with gas or fields, a Strang
// splitting of the Coulomb kicks and the stream step, still second order).
//
//     physics { electromagnetic { model lorentz; coulomb { model shifted; cutoff 1e-3; } } }
#pragma once

#include "slides/collide/cell_grid.h"
#include "slides/core/particle_cloud.h"
#include "slides/physics/coulomb.h"

#include <cstdint>
#include <span>
#include <vector>

namespace slides {

class CoulombForces {
public:
    /// Particles outside `domain` take no part: they escape at the step's end.
    CoulombForces(const CoulombSettings& settings, double particleDensity, const Box& domain);

    /// The forces at the cloud's state (cloud.charge sized), unless they are those of the last
    /// evaluation already (same particles at the same positions).
    void evaluate(const ParticleCloud& cloud);

    /// Particle i's force of the last evaluation [N], by cloud index.
    const std::vector<Vec3>& forces() const { return forces_; }

    /// The pairs' potential energy of the last evaluation [J] (the sum of U over the pairs).
    double potentialEnergy() const;

    /// Advances every particle's velocity by its force over half its step; densities: each
    /// particle's own ρp where species differ (integrate/species_values.h), else empty.
    void halfKick(ParticleCloud& cloud, const std::vector<double>& stepLengths,
                  std::span<const double> densities) const;

private:
    /// A pair closer than the cut-off: its particles (cloud indices) and the force on the first.
    struct Pair {
        std::uint32_t first;
        std::uint32_t second;
        Vec3 force;
        double energy;
    };

    bool isCurrent(const ParticleCloud& cloud) const;

    CoulombSettings settings_;
    double particleDensity_;
    Box domain_;
    CellGrid grid_;
    std::vector<Pair> pairs_;
    /// pairOf_[pairStart_[i] … pairStart_[i + 1]) are particle i's pairs, as 2 p + side (side 1:
    /// the particle is the pair's second).
    std::vector<std::uint32_t> pairStart_, pairOf_;
    std::vector<Vec3> forces_;
    std::vector<ParticleId> evaluatedIds_; ///< the cloud of the last evaluation
    std::vector<Vec3> evaluatedPositions_;
};

} // namespace slides
