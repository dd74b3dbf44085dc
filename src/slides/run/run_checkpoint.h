// Run checkpoint: a stepper's whole state into checkpoint.h5, and a stepper continued from it
// with every later step bit for bit the one the interrupted run would have taken.
//
//     slides-track CASE --checkpoint-every 500     // steps; writes CASE/slides/checkpoint.h5
//     slides-track CASE --restart                  // continues from it
//     mpirun -np 3 slides-track CASE -parallel --restart   // from a checkpoint of any rank count
// The file's layout, its atomic write and its checks are io/checkpoint.h's; this file knows the
// stepper: its snapshot, and the soft-sphere springs. A parallel run's checkpoint is the whole
// run's, gathered on rank 0 as a frame is (run/rank_gather.h), without the particles' mesh
// locations (a part's tetrahedra): a serial run or any rank count restarts from it, and a
// parallel run from a serial one.
#pragma once

#include "slides/io/checkpoint.h"
#include "slides/io/run_output.h"
#include "slides/run/rank_communicator.h"
#include "slides/run/stepper.h"

namespace slides {

/// Writes output->directory()/checkpoint.h5 atomically (output on the rank that writes, else
/// null); throws OutputError. Collective in a parallel run (exits and surfaces: as gatherRun's).
void writeCheckpoint(const RunOutput* output, const Stepper& stepper, double nextFrameTime,
                     const RunTimes& times, const RunFingerprint& fingerprint,
                     const RankCommunicator& ranks, std::size_t exits, std::size_t surfaces);

/// Continues stepper from a checkpoint's state (its frames stay with the caller). Collective in
/// a parallel run: every rank gives the whole state, rank 0 keeps the counters that ranks sum
/// and the arrivals, and each rank the particles its part holds.
void resumeFromCheckpoint(Stepper& stepper, CheckpointState&& state, const RankCommunicator& ranks);

} // namespace slides
