// Rank gather: a parallel run's state collected on rank 0 for the writers, as one serial run's.
//
// Frames, arrivals and the summary are written by rank 0 alone from this: the particles of
// every rank sorted by id, the arrivals sorted by id, the counters summed (the injection and
// step counters, alike on every rank, taken as they are). Simple and exact; it costs one gather
// of every particle's arrays to rank 0 at every frame (about 130 bytes a particle).
//
//     const GatheredRun run = gatherRun(stepper.snapshot(), ranks, exits, surfaces);
#pragma once

#include "slides/io/run_snapshot.h"
#include "slides/run/rank_communicator.h"

namespace slides {

struct GatheredRun {
    RunCounters counters;
    ParticleCloud cloud;
    std::vector<Arrival> arrivals;
    std::optional<long> neighbourListBuilds;

    /// (adaptiveRungeKutta is refused in parallel runs: no adaptive steps to gather.)
    RunSnapshot snapshot() const {
        return {counters, cloud, arrivals, neighbourListBuilds, std::nullopt};
    }
};

/// Every rank's part of the run, on rank 0 (elsewhere the counters only); exits: entries of
/// escapedThrough (1 + the carrier's patches), surfaces: entries of rebounds. Collective.
GatheredRun gatherRun(const RunSnapshot& mine, const RankCommunicator& ranks, std::size_t exits,
                      std::size_t surfaces);

} // namespace slides
