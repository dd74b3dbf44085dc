#include "slides/run/run_checkpoint.h"

#include "slides/run/rank_gather.h"

namespace slides {

void writeCheckpoint(const RunOutput* output, const Stepper& stepper, double nextFrameTime,
                     const RunTimes& times, const RunFingerprint& fingerprint,
                     const RankCommunicator& ranks, std::size_t exits, std::size_t surfaces) {
    std::optional<SpringColumns> springs;
    if (const SoftSphereCollisions* softSpheres = stepper.softSpheres()) {
        springs.emplace();
        for (const ContactSpring& spring : softSpheres->springs()) {
            springs->first.push_back(spring.first);
            springs->second.push_back(spring.second);
            springs->displacement.push_back(spring.displacement);
            springs->largestOverlap.push_back(spring.largestOverlap);
        }
    }
    if (!ranks.parallel())
        return writeCheckpoint(output->directory(), stepper.snapshot(),
                               springs ? &*springs : nullptr, output->frames(), nextFrameTime,
                               times, fingerprint);
    GatheredRun run = gatherRun(stepper.snapshot(), ranks, exits, surfaces);
    if (!output) return;
    run.cloud.carrierLocation.assign(run.cloud.size(), -1); // this rank count's tetrahedra
    writeCheckpoint(output->directory(), run.snapshot(), springs ? &*springs : nullptr,
                    output->frames(), nextFrameTime, times, fingerprint);
}

void resumeFromCheckpoint(Stepper& stepper, CheckpointState&& state,
                          const RankCommunicator& ranks) {
    if (ranks.rank() != 0) { // what gatherRun sums over the ranks is rank 0's
        RunCounters& counters = state.counters;
        counters.escaped = 0;
        counters.particleSteps = 0;
        counters.collisions = 0;
        counters.escapedThrough.assign(counters.escapedThrough.size(), 0);
        counters.rebounds.assign(counters.rebounds.size(), 0);
        state.arrivals.clear();
    }
    std::vector<ContactSpring> springs;
    for (std::size_t i = 0; i < state.springs.first.size(); ++i)
        springs.push_back({state.springs.first[i], state.springs.second[i],
                           state.springs.displacement[i], state.springs.largestOverlap[i]});
    stepper.resume(state.counters, std::move(state.cloud), std::move(state.arrivals),
                   std::move(springs));
}

} // namespace slides
