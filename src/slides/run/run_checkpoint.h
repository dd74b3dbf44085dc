// Run checkpoint: a stepper's whole state into checkpoint.h5, and a stepper continued from it
// with every later step bit for bit the one the interrupted run would have taken.
//
//     slides-track CASE --checkpoint-every 500     // steps; writes CASE/slides/checkpoint.h5
//     slides-track CASE --restart                  // continues from it
// The file's layout, its atomic write and its checks are io/checkpoint.h's; this file knows the
// stepper: its snapshot, and the soft-sphere springs.
#pragma once

#include "slides/io/checkpoint.h"
#include "slides/io/run_output.h"
#include "slides/run/stepper.h"

namespace slides {

/// Writes output.directory()/checkpoint.h5 atomically; throws OutputError.
void writeCheckpoint(const RunOutput& output, const Stepper& stepper, double nextFrameTime,
                     const RunTimes& times, const RunFingerprint& fingerprint);

/// Continues stepper from a checkpoint's state (its frames stay with the caller).
void resumeFromCheckpoint(Stepper& stepper, CheckpointState&& state);

} // namespace slides
