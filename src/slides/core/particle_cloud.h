// ParticleCloud: the moving particles as structure of arrays with stable ids.
//
// One array per particle field (HOOMD-blue ParticleData, Cabana slices). A particle's id never
// changes; its index does, because a particle that leaves the cloud (arrives at a surface or
// escapes) is replaced by the last one. Per-particle model state added by later models lives in
// arrays beside these and is moved by the same swap.
#pragma once

#include "slides/core/eddy_state.h"
#include "slides/core/vector.h"

#include <cstdint>
#include <vector>

namespace slides {

using ParticleId = std::uint64_t;

/// Where a particle is in its life; written to the output as an integer field `state`.
enum class ParticleState : std::int32_t { active = 0, arrived = 1, escaped = 2 };

struct ParticleCloud {
    std::vector<ParticleId> id;
    std::vector<Vec3> position; ///< [m]
    std::vector<Vec3> velocity; ///< [m/s]
    std::vector<double> radius; ///< [m]
    // Model state: empty while its model is off, else one entry per particle (the stepper
    // fills the entries of particles as they enter).
    std::vector<EddyState> eddy;     ///< turbulent dispersion (physics/dispersion.h)
    std::vector<double> temperature; ///< θ [K], heat transfer (physics/heat_transfer.h)

    std::size_t size() const { return id.size(); }
    bool empty() const { return id.empty(); }

    void reserve(std::size_t count);
    void add(ParticleId particleId, const Vec3& x, const Vec3& v, double particleRadius);
    /// Removes the particle at index by moving the last particle into its place.
    void removeAt(std::size_t index);
};

} // namespace slides
