// Injector: puts particles on the nozzle disc with the local gas velocity plus a random
// cross-span velocity, at a given rate or all at the start; or, in mode lattice, all at the
// start on the sites of a simple cubic lattice, with the gas velocity plus a random one uniform
// in [−spread, spread] per component.
//
// Particle k (id k) is injected at t_k = k / rate (or t = 0). Its radius, position on the disc
// (uniform in area) and cross-span direction come from counter-based random streams keyed by
// (seed, k), so they do not depend on the time step, the thread count or the other particles.
// A particle due within a step is added at the start of that step, on the nozzle, and the
// stepper advances it over the rest of the step only (run/stepper.h).
//
//     injection { mode rate; rate 2e5; crossSpanSpeed 0.5; seed 1; }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/jet_frame.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/injection_settings.h"

namespace slides {

/// Where particle id starts in injection mode lattice: its site's centre.
Vec3 latticeSite(const InjectionSettings& injection, ParticleId id);

/// A radius drawn from the distribution for particle id (truncated by redrawing).
double drawRadius(const RadiusDistribution& distribution, std::uint64_t seed, ParticleId id);

class Injector {
public:
    /// Injects particles.count particles of particles.radius from the nozzle.
    Injector(const InjectionSettings& injection, const JetNozzle& nozzle,
             const ParticleSettings& particles);

    /// Adds every particle due before `until` that is not yet in the cloud; the gas is
    /// sampled once for the whole batch.
    void injectUntil(double until, double time, const CarrierField& carrier, ParticleCloud& cloud);

    long injected() const { return injected_; }
    /// Continues as if particles 0 … injected − 1 had been injected (restart).
    void resumeAfter(long injected) { injected_ = injected; }
    bool finished() const { return injected_ == count_; }
    /// Time at which particle id enters [s].
    double injectionTime(ParticleId id) const;

private:
    InjectionSettings injection_;
    JetNozzle nozzle_;
    long count_;
    RadiusDistribution radius_;
    long injected_ = 0;
    std::vector<Vec3> positions_;
    std::vector<Vec3> randomVelocities_; ///< the random part of each start velocity
    CarrierSample gas_;
};

} // namespace slides
