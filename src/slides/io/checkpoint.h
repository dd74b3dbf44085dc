// Checkpoint: the whole state of a run in one file, from which `slides-track CASE --restart`
// continues with results bit-identical to a run never interrupted.
//
//     slides-track CASE --checkpoint-every 500     // steps; writes CASE/slides/checkpoint.h5
//     slides-track CASE --restart                  // continues from it
//
// checkpoint.h5 is a copy of the run's particles.h5.partial (its frames so far, when HDF5
// output is on) plus a /checkpoint group: every per-particle array of the cloud
// (ParticleCloud::forEachArray), the arrivals, the stepper's counters, the frames written and
// the next frame time; attributes name the software version, the hash of the case dictionary
// and the time step it belongs to. It is written under a temporary name, flushed and renamed
// (io/atomic_file.h), so a run killed at any moment leaves the previous checkpoint whole; its
// datasets carry Fletcher-32 checksums, so a damaged file is refused rather than resumed.
#pragma once

#include "slides/run/stepper.h"
#include "slides/io/frame_record.h"
#include "slides/io/run_output.h"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace slides {

inline constexpr const char* checkpointFileName = "checkpoint.h5";

/// What identifies the run a checkpoint belongs to; a restart must match it.
struct RunFingerprint {
    std::string version;              ///< SLIDES-track version
    std::uint64_t dictionaryHash = 0; ///< FNV-1a of constant/slidesProperties' bytes
    double dt = 0;                    ///< time step [s] (after command-line overrides)
};

/// The fingerprint of the scene as read from its dictionary.
RunFingerprint fingerprintOf(const Scene& scene);

/// Everything needed to continue a run.
struct RunState {
    StepperCounters counters;
    ParticleCloud cloud;
    std::vector<Arrival> arrivals;
    std::vector<ContactSpring> springs; ///< of soft-sphere contacts touching
    std::vector<FrameRecord> frames;
    double nextFrameTime = 0; ///< [s]
};

/// Writes output.directory()/checkpoint.h5 atomically; throws OutputError.
void writeCheckpoint(const RunOutput& output, const Stepper& stepper, double nextFrameTime,
                     const RunFingerprint& fingerprint);

/// Reads directory/checkpoint.h5 and, when HDF5 output is on, restores particles.h5.partial
/// from it. Throws InputError naming the checkpoint when it is missing, damaged, or written
/// by another version, for another case dictionary or another time step.
RunState resumeFromCheckpoint(const std::filesystem::path& directory, const Scene& scene,
                              const RunFingerprint& fingerprint);

} // namespace slides
