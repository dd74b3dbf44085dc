// Run report: what a run tells its user — the description of the resolved scene printed at
// the start, summary.json's content (io/summary.h) from the resolved scene and the final
// snapshot, and the closing lines on the console.
//
//     slides-track 0.2.0: case foamCases/analyticSpray
//       carrier    analytic sech² jet ...
//     done: t = 0.01 s in 1000 steps, ...
#pragma once

#include "slides/io/run_output.h"
#include "slides/io/summary.h"
#include "slides/run/resolved_scene.h"

#include <nlohmann/json.hpp>

namespace slides {

/// Prints the scene, its analysis, the time step and the threads to stdout.
void describeRun(const ResolvedScene& resolved, int threads);

/// What the frames of a run of scene hold.
RunOutputSettings runOutputSettings(const Scene& scene);

/// What the summary reports of scene: its settings, and the analysis when one is given.
SummaryInputs summaryInputs(const Scene& scene, const SceneAnalysis* analysis = nullptr);

/// summary.json of the run: the resolved scene's settings and analysis beside the snapshot.
nlohmann::json runSummary(const ResolvedScene& resolved, const RunSnapshot& snapshot,
                          const RunMetrics& metrics);

/// Prints the run's outcome (counts, escapes, deposits) and where its results are.
void reportRunEnd(const RunSnapshot& snapshot, const nlohmann::json& summary,
                  const RunOutput& output, const RunMetrics& metrics);

} // namespace slides
