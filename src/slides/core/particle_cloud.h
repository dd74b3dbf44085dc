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

/// Diameter of a particle of the given radius [m]: the frames' `diameter`, the length of its
/// Reynolds number.
inline double particleDiameter(double radius) { return 2 * radius; }

/// Where a particle is in its life; written to the output as an integer field `state`.
enum class ParticleState : std::int32_t { active = 0, arrived = 1, escaped = 2 };

struct ParticleCloud {
    std::vector<ParticleId> id;
    std::vector<Vec3> position; ///< [m]
    std::vector<Vec3> velocity; ///< [m/s]
    std::vector<double> radius; ///< [m]
    /// A mesh carrier's location (tetrahedron) of each particle (CarrierField::sampleFrom); empty
    /// otherwise.
    std::vector<std::int32_t> carrierLocation;
    /// Per-particle model state (history memory, or adaptiveRungeKutta's next trial sub-step):
    /// stateWidth doubles a particle, moved with it; empty when no model keeps state.
    std::vector<double> modelState;
    std::size_t stateWidth = 0;
    // Model state: empty while its model is off, else one entry per particle (the stepper
    // fills the entries of particles as they enter).
    std::vector<EddyState> eddy;       ///< turbulent dispersion (physics/dispersion.h)
    std::vector<double> temperature;   ///< θ [K], heat transfer (physics/heat_transfer.h)
    std::vector<Vec3> angularVelocity; ///< ω [rad/s], spin (physics/spin.h) or collisions
    /// Soft-sphere contact load at the end of the last step (collide/soft_sphere_collisions.h).
    std::vector<Vec3> contactForce;  ///< [N]
    std::vector<Vec3> contactTorque; ///< [N m]
    std::vector<double> charge;      ///< q [C], electromagnetic forces (physics/electromagnetic.h)

    std::size_t size() const { return id.size(); }
    bool empty() const { return id.empty(); }

    void reserve(std::size_t count);
    void add(ParticleId particleId, const Vec3& x, const Vec3& v, double particleRadius);
    /// Removes the particle at index by moving the last particle into its place.
    void removeAt(std::size_t index);

    /// Calls visit(name, array) for every array of one entry per particle, so that removal,
    /// checkpoints and restarts (io/checkpoint.h) handle each array a model adds once it is
    /// listed here. Arrays of models that are off are empty. (modelState, stateWidth entries a
    /// particle, is handled beside them.)
    template <typename Cloud, typename Visitor>
    static void forEachArray(Cloud& cloud, Visitor visit) {
        visit("id", cloud.id);
        visit("position", cloud.position);
        visit("velocity", cloud.velocity);
        visit("radius", cloud.radius);
        visit("carrierLocation", cloud.carrierLocation);
        visit("eddy", cloud.eddy);
        visit("temperature", cloud.temperature);
        visit("angularVelocity", cloud.angularVelocity);
        visit("contactForce", cloud.contactForce);
        visit("contactTorque", cloud.contactTorque);
        visit("charge", cloud.charge);
    }
};

} // namespace slides
