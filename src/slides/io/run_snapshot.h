// Run snapshot: the state of a run at one instant as plain values — time, counters, the cloud's
// arrays and the arrivals — which the writers (frames, summary, checkpoint) take instead of the
// stepper that produced it (run/stepper.h fills one: Stepper::snapshot()).
#pragma once

#include "slides/core/particle_cloud.h"
#include "slides/integrate/adaptive_steps.h"
#include "slides/surfaces/arrival.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace slides {

/// The counters of a run: what a checkpoint holds besides the cloud, arrivals and springs.
struct RunCounters {
    double time = 0; ///< [s]
    long steps = 0;
    long injected = 0;
    long escaped = 0;
    std::uint64_t particleSteps = 0;
    /// Escapes by exit: [0] the domain box (or a patch not known), [1 + p] carrier patch p.
    std::vector<std::uint64_t> escapedThrough;
    long collisions = 0;                 ///< particle–particle contacts
    std::vector<std::uint64_t> rebounds; ///< per surface
    /// Particles re-injected in place of escaped ones, per injector; empty when none does.
    std::vector<std::uint64_t> reinjected;
};

/// A view of the run's state: valid while the stepper it was taken from is not stepped.
struct RunSnapshot {
    RunCounters counters;
    const ParticleCloud& cloud;           ///< the particles in flight
    const std::vector<Arrival>& arrivals; ///< the particles that arrived, in order
    /// Neighbour-list builds of soft-sphere contacts (a cost), when they are on.
    std::optional<long> neighbourListBuilds;
    /// adaptiveRungeKutta's sub-steps (a cost), when it is the integrator.
    std::optional<AdaptiveSteps> adaptiveSteps;
};

} // namespace slides
