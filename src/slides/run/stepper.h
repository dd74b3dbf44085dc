// Stepper: the loop of one run — inject, sample the carrier, integrate, meet surfaces.
//
// Per step of length h (the last one shortened to end exactly at time.endTime):
//   0. an unsteady carrier holds what the step's times [t, t + h] need (a series' levels);
//      with a mesh carrier, every few steps the cloud is put in the order of its tetrahedra
//      (core/particle_order.h), so the walks and samples read the mesh nearly in order;
//   1. particles due before t + h enter (integrate/injector.h); one due at t_k inside the step
//      is advanced only over its remainder t + h − t_k, as a parcel's step fraction in OpenFOAM
//      (the carrier is still sampled at t and t + h/2 for the whole batch: exact for the
//      steady carriers); in a parallel run each enters only on the rank whose part of the mesh
//      holds it;
//   1a. with soft spheres, at the first step and every cellOrderInterval steps the cloud (new
//      particles included) is put in the order of the contact grid's cells instead, so that
//      each thread's particles are those of its contacts;
//   1b. where the injectors' species differ, each particle's density, body acceleration (and
//      with heat transfer specific heat) is held for the stages that take them
//      (integrate/species_values.h);
//   2. the carrier is sampled once for the whole cloud;
//   2b. with turbulent dispersion, the gas velocity each particle sees gets its time-averaged
//      eddy fluctuation over the step (integrate/turbulent_dispersion.h);
//   3. each particle is advanced by the chosen integrator (integrate/integrator.h) under drag
//      (physics/drag.h) and gravity with buoyancy (physics/body_force.h) — without gas
//      (carrier none) by gravity alone, exactly; exponentialMidpoint
//      samples the carrier a second time at the half-step positions, block by block so the
//      samples and the prediction live only in a thread's cache-sized scratch (and takes the
//      sample of 2 there too when no other stage reads it);
//      with an unsteady term on (history, added mass, pressure gradient, lift, spin) the
//      Maxey–Riley step (integrate/maxey_riley.h) replaces the integrator, on the sample of 2
//      (with its eddy fluctuations) and a second one at its predicted ends;
//      adaptiveRungeKutta sub-steps each particle within the step, sampling the carrier stage by
//      stage for a block of particles (integrate/adaptive_runge_kutta_batch.h; on charged
//      particles with the Lorentz force), and keeps each particle's next trial sub-step as its
//      model state between steps;
//   3b. with heat transfer, each particle's temperature relaxes toward the gas temperature
//      (integrate/particle_heating.h);
//   3c. with particle collisions on, contacts between particles during the step are resolved
//      by impulses (collide/particle_collisions.h); with soft spheres
//      (collide/soft_sphere_collisions.h) instead, the contact loads kick each particle's
//      velocity and spin by half a step before 3 and, computed anew at the step's end, after
//      it: velocity Verlet with the stream step as its drift (second order, symplectic
//      without a gas);
//   3c'. with Coulomb forces between charged particles (collide/coulomb_forces.h), the same
//      velocity-Verlet kicks: half a step by the force at the step's start before 3 and by the
//      force at its end after it (evaluated once per position: the end's serves the next start);
//   3d. in a parallel run, each particle goes to the rank whose part of the mesh holds it
//      (run/rank_exchange.h), so the next stage finds its location current;
//   4. a particle whose path touched a surface or the deposit is absorbed, sticks or rebounds
//      (surfaces/surface_impacts.h): absorbed and stuck ones are frozen there as an Arrival;
//      one that left the domain box, or the carrier's mesh, has escaped; both leave the cloud;
//      an escaped particle of an injector with reinjectEscaped is replaced at the step's end
//      by a new one of that injector (integrate/injector_set.h).
// On a 2-D carrier (a mesh between `empty` patches) the particles are held in its plane after
// injection, the eddies' draw, the stream step and the surfaces (integrate/plane_constraint.h).
// The step is the ordered list of these stages, each present only when its term is on, built
// once at construction (Stepper::buildStages): a new stage is added there.
// The particle loop runs in parallel; each particle's update depends only on its own state,
// so results are identical for any thread count. A non-finite position or velocity stops the
// run with an error naming the particle, instead of propagating.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/collide/coulomb_forces.h"
#include "slides/collide/particle_collisions.h"
#include "slides/collide/soft_sphere_collisions.h"
#include "slides/config/scene.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/adaptive_steps.h"
#include "slides/integrate/charged_motion.h"
#include "slides/integrate/injector_set.h"
#include "slides/integrate/maxey_riley.h"
#include "slides/integrate/particle_heating.h"
#include "slides/integrate/plane_constraint.h"
#include "slides/integrate/species_values.h"
#include "slides/integrate/turbulent_dispersion.h"
#include "slides/io/run_snapshot.h"
#include "slides/physics/drag.h"
#include "slides/run/rank_exchange.h"
#include "slides/surfaces/arrival.h"
#include "slides/surfaces/surface_impacts.h"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace slides {

class Stepper {
public:
    /// Keeps references to scene and carrier: both must outlive the stepper. A parallel run
    /// passes its exchange (run/rank_exchange.h), which then is a stage of every step.
    Stepper(const Scene& scene, const CarrierField& carrier, RankExchange* exchange = nullptr);
    Stepper(Scene&&, const CarrierField&) = delete;
    Stepper(const Scene&, CarrierField&&) = delete;

    /// Advances the cloud by one time step.
    void step();
    /// Whether the run is over: end time reached, or all particles done (stopWhenAllDone).
    bool finished() const;

    double time() const { return time_; }
    long steps() const { return steps_; }
    std::uint64_t particleSteps() const { return particleSteps_; }
    long injected() const { return injectors_.injected(); }
    long escaped() const { return escaped_; }
    /// Escapes by exit, as RunCounters::escapedThrough.
    const std::vector<std::uint64_t>& escapedThrough() const { return escapedThrough_; }
    const ParticleCloud& cloud() const { return cloud_; }
    const std::vector<Arrival>& arrivals() const { return arrivals_; }
    const SurfaceImpacts& surfaceImpacts() const { return surfaces_; }
    /// Particle–particle contacts resolved (impulses) or begun (soft spheres) so far.
    long collisions() const;
    /// The soft-sphere contacts, when collisions.model is softSphere.
    const SoftSphereCollisions* softSpheres() const {
        return softSpheres_ ? &*softSpheres_ : nullptr;
    }

    /// The Coulomb forces, when physics.electromagnetic.coulomb is on.
    const CoulombForces* coulombForces() const { return coulomb_ ? &*coulomb_ : nullptr; }

    RunCounters counters() const;
    /// The state now, for the writers (io/run_snapshot.h).
    RunSnapshot snapshot() const;
    /// Continues from a checkpoint's state: every later step is bit for bit the one the
    /// stepper that wrote the checkpoint would have taken. In a parallel run every rank is given
    /// the whole cloud, and each keeps the particles its part of the mesh holds (located anew:
    /// the checkpoint may come from another rank count).
    void resume(const RunCounters& counters, ParticleCloud cloud, std::vector<Arrival> arrivals,
                std::vector<ContactSpring> springs = {});

private:
    /// One stage of a step of length h, in the order of the header's list.
    using Stage = void (Stepper::*)(double h);
    /// The stages of this scene's step, each only when its term is on (built once).
    void buildStages();
    /// 0. an unsteady carrier made ready for the step's times [t, t + h].
    void holdCarrierTimes(double h);
    /// 0. every few steps, the cloud in the order of its carrier locations.
    void orderInMemory(double h);
    /// Every cellOrderInterval steps, after the new particles have entered: the cloud in the
    /// order of the contact grid's cells (core/particle_order.h).
    void orderByContactCells(double h);
    /// 1. particles due before t + h enter; their step lengths.
    void inject(double h);
    /// The arrays of the models that are on sized for the particles entered at [from, size),
    /// with their start values (location unknown, no spin, injection temperature, charge).
    void equipNewParticles(std::size_t from);
    /// 3c (soft spheres). The contact loads kick velocity and spin by half a step.
    void kickByContacts(double h);
    /// 3c'. The Coulomb forces at the particles' positions kick their velocities by half a step.
    void kickByCoulombForces(double h);
    /// The paths' starts (positions, velocities) before the stream step.
    void recordPathStarts(double h);
    /// 2. the carrier sampled once for the whole cloud at t.
    void sampleGas(double h);
    /// 2b. eddy fluctuations added to the gas velocity each particle sees.
    void disperse(double h);
    /// 3. the stream step through the gas: the integrator, or the Maxey–Riley step.
    void advance(double h);
    /// 3. the stream step without gas (carrier none): gravity only, exactly.
    void flyBallistically(double h);
    /// 1b. (differing species only) each particle's species values for the step's stages:
    /// particleSpecies_, particleDensities_ and particleAccelerations_.
    void holdSpeciesValues(double h);
    /// The values holdSpeciesValues held (empty spans when the particles are alike).
    SpeciesValues speciesValues() const;
    /// 3b. temperatures relax toward the gas temperature.
    void heat(double h);
    /// 3c (impulses). Contacts between particles during the step.
    void collide(double h);
    /// 3c (soft spheres). Loads at the step's end, the second half kick, wall rebounds counted.
    void kickByNewContacts(double h);
    /// 3d. (parallel runs) particles handed to the rank that holds them.
    void exchangeAcrossRanks(double h);
    /// 4. particles that touched a surface or left the domain leave the cloud.
    void meetSurfaces(double h);
    /// 2-D carrier: the particles back in the plane after a stage that may leave it.
    void holdInPlane(double h);
    /// 2-D carrier: the gas velocity seen, with its eddy fluctuation, projected on the plane.
    void holdEddiesInPlane(double h);
    /// Where escaping particle i left: 1 + the carrier's patch it crossed, or 0 (domain box).
    std::size_t exitOf(std::size_t i) const;
    /// Particle i's temperature over this step, with heat transfer.
    std::optional<StepTemperature> temperatureOver(std::size_t i) const;
    /// The carrier at points, from and updating their locations when the carrier keeps them.
    void sampleCarrier(std::span<const Vec3> points, std::span<std::int32_t> locations, double time,
                       CarrierNeeds needs, CarrierSample& out) const;
    /// 3. the exponential midpoint rule, block by block.
    void advanceByMidpointRule(double h);
    /// 3. the adaptive Dormand–Prince sub-steps, block by block, the carrier at t + h/2.
    void advanceAdaptively(double h);
    /// Whether the gas is sampled at the step's start for the whole cloud (stage 2): when
    /// dispersion, heating or the Maxey–Riley step read it, or the integrator is an explicit or
    /// exponential Euler step; the midpoint and adaptive schemes sample their blocks themselves.
    bool samplesGasForAll() const;

    const Scene& scene_;
    const CarrierField& carrier_;
    DragParameters drag_;
    Vec3 bodyAcceleration_;
    InjectorSet injectors_;
    CarrierNeeds needs_; ///< k, ε and T when dispersion or heat transfer is on
    TurbulentDispersion dispersion_;
    ParticleHeating heating_;
    ParticleCloud cloud_;
    std::vector<Arrival> arrivals_;
    double time_ = 0;
    long steps_ = 0;
    long escaped_ = 0;
    std::vector<std::uint64_t> escapedThrough_;
    std::uint64_t particleSteps_ = 0;
    std::optional<MaxeyRileyStepper> maxeyRiley_;     ///< when an unsteady term is on
    std::optional<ChargedMotion> chargedMotion_;      ///< with electromagnetic forces
    std::optional<ParticleCollisions> collisions_;    ///< when collisions.model is impulse
    std::optional<SoftSphereCollisions> softSpheres_; ///< when collisions.model is softSphere
    std::optional<CoulombForces> coulomb_;            ///< with electromagnetic.coulomb
    std::optional<PlaneConstraint> plane_;            ///< when the carrier is 2-D
    SurfaceImpacts surfaces_;
    bool tracksSpin_ = false; ///< ω kept: spin, or any impulse contact with friction
    std::vector<Stage> stages_;
    RankExchange* exchange_ = nullptr; ///< parallel runs only

    // Scratch, reused every step.
    CarrierSample gas_;
    std::vector<double> stepLengths_; ///< h, or the remainder of the step for new particles
    /// Particles of differing species (scene.particles.species): each one's ρp and body
    /// acceleration in this step; empty when the particles are alike.
    std::vector<std::int32_t> particleSpecies_;
    std::vector<double> particleDensities_;
    std::vector<Vec3> particleAccelerations_;
    std::vector<double> particleSpecificHeats_;    ///< with heat transfer
    std::vector<double> particleSusceptibilities_; ///< with magnetisation
    std::vector<Vec3> speciesAccelerations_;       ///< one a species
    std::vector<Vec3> startPositions_;
    std::vector<Vec3> startVelocities_;
    std::vector<double> startTemperatures_; ///< with heat transfer
    /// A mesh carrier's cells of the Maxey–Riley step's predicted ends.
    std::vector<std::int32_t> midpointLocations_;
    /// One thread's scratch of the midpoint rule: a block's samples, its predicted state at
    /// t + h/2 and their mesh locations.
    struct MidpointScratch {
        CarrierSample gas;
        CarrierSample midpointGas;
        std::vector<Vec3> position;
        std::vector<Vec3> velocity;
        std::vector<std::int32_t> locations;
    };
    /// Particles a block of the schemes that sample the carrier themselves (the midpoint rule,
    /// the adaptive sub-steps): a block's scratch stays in the core's cache.
    static constexpr std::size_t samplingBlock = 1024;
    std::vector<MidpointScratch> midpointScratch_; ///< one a thread
    std::vector<std::uint8_t> fliesOn_;      ///< particles whose path meets nothing (meetSurfaces)
    std::vector<Vec3> eddyVelocities_;       ///< adaptiveRungeKutta with dispersion: each ū'
    std::vector<LorentzRates> lorentzRates_; ///< adaptiveRungeKutta with charges: qE/m, qB/m
    AdaptiveSteps adaptiveSteps_;            ///< adaptiveRungeKutta's sub-steps so far
};

} // namespace slides
