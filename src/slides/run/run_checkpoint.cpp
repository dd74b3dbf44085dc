#include "slides/run/run_checkpoint.h"

namespace slides {

void writeCheckpoint(const RunOutput& output, const Stepper& stepper, double nextFrameTime,
                     const RunTimes& times, const RunFingerprint& fingerprint) {
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
    writeCheckpoint(output.directory(), stepper.snapshot(), springs ? &*springs : nullptr,
                    output.frames(), nextFrameTime, times, fingerprint);
}

void resumeFromCheckpoint(Stepper& stepper, CheckpointState&& state) {
    std::vector<ContactSpring> springs;
    for (std::size_t i = 0; i < state.springs.first.size(); ++i)
        springs.push_back({state.springs.first[i], state.springs.second[i],
                           state.springs.displacement[i], state.springs.largestOverlap[i]});
    stepper.resume(state.counters, std::move(state.cloud), std::move(state.arrivals),
                   std::move(springs));
}

} // namespace slides
