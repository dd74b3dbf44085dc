// Scene analysis as JSON: the figures, the decision table and the time step with its limits —
// the "sceneAnalysis" of summary.json (analysis/scene_analysis.h).
//
//     "sceneAnalysis": { "terms": [ { "term": "history", "decision": "off", ... } ], ... }
#pragma once

#include "slides/analysis/scene_analysis.h"

#include <nlohmann/json.hpp>

namespace slides {

/// The scene analysis as JSON: figures, the decision table, the time step and its limits.
nlohmann::json sceneAnalysisJson(const SceneAnalysis& analysis);

} // namespace slides
