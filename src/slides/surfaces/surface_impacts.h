// SurfaceImpacts: what happens where a particle's path meets a surface or the deposit —
// absorbed, stuck (Eq. 5.9) or rebounded by the impulse law (Eq. 2.15–2.33).
//
// The first touch along the step's chord x₀ → x₁ is sought among the planes
// (surfaces/plane_contact.h), the mesh's wall patches (surfaces/patch_wall.h) and the deposited
// particles (surfaces/deposit.h); n̂ is the plane's, the patch face's or the line of centres. At the
// touch, the particle's velocity is that of the chord's fraction s, v_c = v₀ + s (v₁ − v₀):
//   absorb  — the arrival is recorded there and the particle leaves;
//   deposit — if v_n = −v_c·n̂ is below Eq. 5.9's limit for the pair (particle–surface, or
//             particle–deposited particle), it sticks: recorded as an arrival, added to the
//             deposit, and leaves; otherwise it rebounds;
//   erode   — rebounds as below, and loads the damage grid of the surface's porous layer with
//             the impact's Hertz loads (surfaces/erosion_grid.h, Section 5.2);
//   rebound — (a soft wall under collisions.model softSphere: not met here, its contact forces
//             act in collide/soft_sphere_collisions.h; otherwise)
//             impulse J against a rigid body (collide/impulse.h, restitution from
//             physics/restitution.h): v₁ += J/m, ω += r × J / I, and x₁ += (1 − s) h J/m, the
//             rest of the step flown with the new velocity.
// With temperatures tracked, a rebound heats the particle by the energy it dissipates, and a
// particle that sticks by all its kinetic energy (Eq. 2.117; a rigid wall or the deposit takes
// none of it).
// After a rebound the rest of the chord, from the contact point, is searched again (up to
// four contacts a step), so a particle bouncing in a corner or off the deposit onto the target
// is caught. A hit on the deposit inherits the interaction and adhesion of the surface it grew on,
// with the particles' own material on both sides.
//
//     surfaces { target { type plane; point (0.06 0 0); normal (-1 0 0); interaction deposit; } }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/injection_settings.h"
#include "slides/physics/adhesion.h"
#include "slides/physics/heat_transfer.h"
#include "slides/surfaces/arrival.h"
#include "slides/surfaces/deposit.h"
#include "slides/surfaces/erosion_grid.h"
#include "slides/surfaces/patch_wall.h"
#include "slides/surfaces/surface_settings.h"

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <vector>

namespace slides {

enum class ImpactResult { none, rebounded, arrived };

/// A particle's lumped temperature over its step (integrate/particle_heating.h): at the step's
/// start and the gas temperature it relaxed toward; an arrival takes its value at the touch.
struct StepTemperature {
    double start = 0; ///< [K]
    double gas = 0;   ///< [K]
};

class SurfaceImpacts {
public:
    /// Collisions give restitution, friction and which surfaces are soft walls; deposition the
    /// adhesion of deposit surfaces; heatTransfer whether temperatures are tracked. The carrier
    /// gives the triangles of the surfaces of type patch.
    SurfaceImpacts(const std::vector<Surface>& surfaces, const CollisionSettings& collisions,
                   const AdhesionSettings& deposition, const ParticleSettings& particles,
                   HeatTransferModel heatTransfer, const CarrierField& carrier);

    /// Meets particle i, which flew from start (velocity startVelocity) to its current state
    /// over stepLength, ending at time stepEnd (with heat transfer, its temperature over the
    /// step). On `arrived`, arrival holds the record.
    ImpactResult meet(ParticleCloud& cloud, std::size_t i, const Vec3& start,
                      const Vec3& startVelocity, double stepLength, double stepEnd,
                      const std::optional<StepTemperature>& temperature, Arrival& arrival);

    /// Whether a sphere of radius moving from start to end can touch a surface met at the touch
    /// (a soft wall is not) or the indexed deposit: false means meet() would find nothing (a
    /// test safe to run in parallel).
    bool mayTouch(const Vec3& start, const Vec3& end, double radius) const;

    /// Puts a particle that stuck in an earlier run back into the deposit (restart).
    void addToDeposit(const Arrival& stuck) {
        deposit_.add(stuck.position, stuck.radius, stuck.surface, particles_.speciesOf(stuck.id));
    }
    /// Whether any surface meets particles here, at the touch (not only soft walls, which
    /// meet them by forces): without one, meet never changes a particle.
    bool meetsAtTouch() const { return !metAtTouch_.empty(); }
    /// Makes the particles stuck so far obstacles for the next meetings.
    void indexDeposit() { deposit_.index(); }

    const Deposit& deposit() const { return deposit_; }
    /// Per surface: the damage grid of its porous layer, for the surfaces that erode.
    const std::vector<std::optional<ErosionGrid>>& erosion() const { return erosion_; }
    /// Rebounds off each surface (and its deposit) so far.
    const std::vector<std::uint64_t>& rebounds() const { return rebounds_; }
    /// Adds rebounds off surface s met elsewhere (the soft walls of soft-sphere collisions).
    void countRebounds(std::size_t s, std::uint64_t count) { rebounds_.at(s) += count; }
    /// Continues the counts of a checkpointed run (one per surface).
    void resumeRebounds(std::vector<std::uint64_t> rebounds) {
        if (rebounds.size() != rebounds_.size())
            throw std::logic_error("checkpoint's rebound counts do not fit the scene's surfaces");
        rebounds_ = std::move(rebounds);
    }

private:
    /// What is left of a step's path: from start with startVelocity, over length [s].
    struct Path {
        Vec3 start;
        Vec3 velocity;
        double length;
    };
    /// The first contact on the path; a rebound leaves path at the contact point.
    ImpactResult meetFirst(ParticleCloud& cloud, std::size_t i, Path& path, double stepEnd,
                           Arrival& arrival);

    /// Where a sphere at centre overlaps surface s (closer than its radius, in front of it).
    std::optional<PatchTouch> overlapWith(std::size_t s, const Vec3& centre, double radius) const;

    /// Whether impulse contacts heat the particles (Eq. 2.117): collisions.heating, with the
    /// temperatures that heat transfer tracks.
    bool heats() const { return collisions_.heating && heatTransfer_ != HeatTransferModel::none; }
    /// Contacts followed in one step; a particle still bouncing after them flies on.
    static constexpr int maxContactsPerStep = 4;

    std::vector<Surface> surfaces_;
    CollisionSettings collisions_;
    AdhesionSettings deposition_;
    ParticleSettings particles_;
    HeatTransferModel heatTransfer_;
    std::vector<std::optional<PatchWall>> walls_; ///< per surface: its patch, if it is one
    std::vector<std::size_t> metAtTouch_; ///< the surfaces met here, at the touch: not soft walls
    Deposit deposit_;
    std::vector<std::uint64_t> rebounds_;
    std::vector<std::optional<ErosionGrid>> erosion_;
};

} // namespace slides
