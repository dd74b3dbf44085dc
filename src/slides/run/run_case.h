// Run case: one whole run of a case — resolve the scene (run/resolved_scene.h), then step it,
// writing a frame every output.interval, a checkpoint every N steps (run/run_checkpoint.h),
// and at the end the deposit and summary.json (run/run_report.h).
//
//     slides::runCase({.caseDirectory = "foamCases/analyticSpray", .threads = 2});
#pragma once

#include "slides/run/rank_communicator.h"
#include "slides/run/run_options.h"

namespace slides {

/// Runs the case; throws InputError for bad input (before anything is written) and
/// OutputError when the results cannot be written. Under -parallel, every rank of ranks runs
/// its part of the decomposed case and rank 0 writes the results (run/rank_gather.h).
void runCase(const RunOptions& options, const RankCommunicator& ranks = {});

} // namespace slides
