// Injector: one source of particles (integrate/injection_settings.h InjectorSettings), by its
// model:
//   disc  on the nozzle disc (uniform in area) with the local gas velocity plus a random
//         cross-span velocity, at a given rate or all at the start; or, in mode lattice, all at
//         the start on the sites of a simple cubic lattice, with the gas velocity plus a random
//         one uniform in [−spread, spread] per component;
//   cone  on the disc (or its centre, radius 0) with speed s along a direction drawn uniformly
//         over the band of the unit sphere between the inner and outer half-angle about the
//         axis: cos θ uniform in [cos θ_out, cos θ_in], azimuth uniform (Archimedes' hat-box);
//   file  the rows of a file (integrate/particle_file.h): position, velocity, radius, time;
//   patch uniformly over the faces of a mesh patch (integrate/patch_sampler.h), with the given
//         velocity or the gas velocity's part normal to the patch, (U·n) n.
//   ensemble  the rows of a packing (integrate/ensemble.h), at rest, all at the start time.
//
// With collisions on (avoidOverlap), a disc, cone or patch particle is not placed overlapping
// any particle in flight or placed before it: the rule is that its start point is redrawn, from
// the stream (seed, id, attempt), until its sphere is clear of every other sphere whose centre
// lies within the two radii of the box that holds the injector's start points (the disc's, the
// patch's or on a wedge its swept surface's); after 64 attempts (an injector already full) it
// keeps the last draw. Without an overlap the first draw stands, as without the rule. On a 2-D
// carrier the spheres are compared on the mid-plane, where the stepper holds them. A file's rows
// and a lattice are prescribed: placed as given. The spheres near the injector are binned
// (integrate/nearby_spheres.h), so each check is O(1) however many crowd it.
//
// Particle firstId + k is injected at t_k = startTime + k / rate (or startTime; a file row's
// time). Its radius, position and random velocity come from counter-based random streams keyed
// by (seed, id), so they do not depend on the time step, the thread count or the other
// particles. A particle due within a step is added at the start of that step, at its start
// point, and the stepper advances it over the rest of the step only (run/stepper.h).
//
// With reinjectEscaped, the particles that replace escaped ones (integrate/injector_set.h) are
// drawn as its own, keyed by their new ids (beyond every injector's block).
//
//     injection { mode rate; rate 2e5; crossSpanSpeed 0.5; seed 1; reinjectEscaped no; }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/jet_frame.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/injection_settings.h"
#include "slides/integrate/nearby_spheres.h"
#include "slides/integrate/patch_sampler.h"
#include "slides/integrate/size_distribution.h"

#include <optional>
#include <span>

namespace slides {

/// Where particle id starts in injection mode lattice: its site's centre.
Vec3 latticeSite(const InjectionSettings& injection, ParticleId id);

/// A direction drawn uniformly over the cone's band of the unit sphere about axis (unit), from
/// two uniforms on (0, 1); across is a unit vector ⟂ axis.
Vec3 coneDirection(const ConeSettings& cone, const Vec3& axis, const Vec3& across,
                   double uniformPolar, double uniformAzimuth);

class Injector {
public:
    /// Injects particles.count particles of particles.radius from the nozzle.
    Injector(const InjectionSettings& injection, const JetNozzle& nozzle,
             const ParticleSettings& particles);
    explicit Injector(const InjectorSettings& settings, bool avoidOverlap = false);

    /// Adds, on each rank of a decomposed mesh, only the particles its part holds: a start
    /// another rank's part holds is left to that rank, one searched for is kept by the lowest
    /// rank holding it (CarrierField::keepHeldHere).
    void splitAmongRanks() { splitAmongRanks_ = true; }
    /// Adds every particle due before `until` that is not yet in the cloud; the gas is
    /// sampled once for the whole batch.
    void injectUntil(double until, double time, const CarrierField& carrier, ParticleCloud& cloud);
    /// Adds the particles ids (not of its block: those that replace escaped ones) at time,
    /// each drawn as one of its own.
    void reinject(std::span<const ParticleId> ids, double time, const CarrierField& carrier,
                  ParticleCloud& cloud);

    long injected() const { return injected_; }
    /// Continues as if its first `injected` particles had been injected (restart).
    void resumeAfter(long injected) { injected_ = injected; }
    bool finished() const { return injected_ == settings_.count; }
    /// Its particles due before `until` (those in the cloud after injectUntil(until)).
    long dueBefore(double until) const;
    /// Time at which particle id (one of this injector's) enters [s].
    double injectionTime(ParticleId id) const;
    /// Whether particle id is one of this injector's.
    bool owns(ParticleId id) const {
        return id >= settings_.firstId &&
               id - settings_.firstId < static_cast<ParticleId>(settings_.count);
    }
    const InjectorSettings& settings() const { return settings_; }
    /// Sets the spin and temperature a file gives its particles at indices [from, size) of
    /// cloud, where the cloud keeps them (its arrays sized).
    void setStartStates(ParticleCloud& cloud, std::size_t from) const;

private:
    /// Where a particle starts and with which velocity, before the gas is sampled there.
    struct Start {
        Vec3 position;
        Vec3 addedVelocity; ///< added to the gas velocity (disc), or the velocity (cone, file)
        Vec3 patchNormal;   ///< model patch: the normal the gas velocity is projected on
        /// The tetrahedron behind the patch triangle it was drawn on (patchLocations_), or
        /// CarrierField::heldElsewhere; −1 when not known.
        std::int32_t location = -1;
    };
    /// The start of particle id from its draw `attempt`.
    Start drawStart(ParticleId id, std::uint32_t attempt) const;
    /// The starts of the new particles ids, each clear of the others near the injector
    /// (avoidOverlap_) or the first draw.
    void drawStarts(std::span<const ParticleId> ids, const ParticleCloud& cloud);
    /// A box holding every start point a draw gives (disc, cone: the disc; patch: the patch).
    Box startBounds() const;
    /// Of ids, into addedIds_, those this rank adds (split among ranks: those its part holds,
    /// CarrierField::keepHeldHere); the starts' arrays keep theirs, in order. Not split, every
    /// start stays, those drawn on another rank's triangles to be searched for.
    void leaveToOtherRanks(std::span<const ParticleId> ids, const CarrierField& carrier);
    /// Adds the particles ids at time: radius, start, velocity (the gas sampled once).
    void add(std::span<const ParticleId> ids, double time, const CarrierField& carrier,
             ParticleCloud& cloud);

    InjectorSettings settings_;
    RadiusSampler radius_;
    bool startsAtGasVelocity_; ///< disc: gas velocity + random; cone, file: the given velocity
    bool startsAtNormalGasVelocity_; ///< patch without a velocity: (U·n) n
    bool avoidOverlap_;              ///< redraw a start that overlaps a particle near the injector
    bool splitAmongRanks_ = false;
    long injected_ = 0;
    std::vector<ParticleId> ids_;
    std::vector<Vec3> positions_;
    std::vector<Vec3> addedVelocities_;
    std::vector<Vec3> patchNormals_;
    std::optional<PatchSampler> patch_; ///< model patch: its faces, from the carrier
    /// Model patch on a mesh carrier (not swept): the tetrahedron behind each triangle.
    std::vector<std::int32_t> patchLocations_;
    std::vector<ParticleId> addedIds_;    ///< the particles this rank adds of a batch
    std::vector<std::int32_t> locations_; ///< a mesh carrier's: each start's location
    std::vector<std::uint8_t> keep_;      ///< of a batch's starts: whether this rank adds it
    std::vector<double> radii_;
    std::optional<NearbySpheres> nearby_; ///< avoidOverlap_: the spheres near the injector
    CarrierSample gas_;
};

} // namespace slides
