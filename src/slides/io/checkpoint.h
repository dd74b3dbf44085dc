// Checkpoint: the whole state of a run in one file, from which `slides-track CASE --restart`
// continues with results bit-identical to a run never interrupted.
//
//     slides-track CASE --checkpoint-every 500     // steps; writes CASE/slides/checkpoint.h5
//     slides-track CASE --restart                  // continues from it
//
// checkpoint.h5 holds what a restart cannot rebuild from the output already flushed, in a
// /checkpoint group: every per-particle array of the cloud (ParticleCloud::forEachArray), the
// arrivals, the run's counters and times, the time and size of each frame written and the next
// frame time; attributes name the software version, the hash of the case dictionary and the
// time step it belongs to. Its size does not grow with the frames: a restart keeps the .vtp
// frames before it and writes particles.h5.partial anew from them (io/run_output.h). It is written
// under a temporary name, flushed and renamed (io/atomic_file.h), so a run killed at any moment
// leaves the previous checkpoint whole. It is written in HDF5's latest format, whose metadata
// (attributes included) carry checksums, and its datasets carry Fletcher-32 checksums: a damaged
// file is refused rather than resumed.
#pragma once

#include "slides/io/frame_record.h"
#include "slides/io/run_snapshot.h"

#include <cstdint>
#include <filesystem>
#include <optional>
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

/// The fingerprint of a run of this dictionary file with time step dt.
RunFingerprint fingerprintOf(const std::filesystem::path& dictionaryFile, double dt);

/// The tangential springs of the soft-sphere contacts touching, as columns: the ids of the two
/// bodies and the spring's displacement (collide/soft_sphere_collisions.h, ContactSpring).
struct SpringColumns {
    std::vector<std::uint64_t> first, second;
    std::vector<Vec3> displacement;
    std::vector<double> largestOverlap; ///< δ_max of the contact (waltonBraun's unloading)

    template <typename Columns, typename Visitor> static void forEach(Columns& c, Visitor visit) {
        visit("first", c.first);
        visit("second", c.second);
        visit("displacement", c.displacement);
        visit("largestOverlap", c.largestOverlap);
    }
};

/// The run's time so far, every segment before a restart included [s].
struct RunTimes {
    double wallSeconds = 0;     ///< output included
    double steppingSeconds = 0; ///< inside Stepper::step() only
};

/// Everything needed to continue a run.
struct CheckpointState {
    RunCounters counters;
    ParticleCloud cloud;
    std::vector<Arrival> arrivals;
    SpringColumns springs; ///< of soft-sphere contacts touching
    std::vector<FrameRecord> frames;
    double nextFrameTime = 0; ///< [s]
    RunTimes times;
};

/// Writes directory/checkpoint.h5 atomically; springs only with soft-sphere contacts. Throws
/// OutputError.
void writeCheckpoint(const std::filesystem::path& directory, const RunSnapshot& snapshot,
                     const SpringColumns* springs, const std::vector<FrameRecord>& frames,
                     double nextFrameTime, const RunTimes& times,
                     const RunFingerprint& fingerprint);

/// Reads directory/checkpoint.h5. Throws InputError naming it (and the dataset) when it is
/// missing, damaged, or written by another version, for another case dictionary or another
/// time step.
CheckpointState readCheckpoint(const std::filesystem::path& directory,
                               const RunFingerprint& fingerprint);

} // namespace slides
