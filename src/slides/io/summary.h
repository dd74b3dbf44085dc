// Run summary: CASE/slides/summary.json — counts, arrival statistics, speed and the settings.
//
//     { "particles": { "injected": 8000, "arrived": { "target": 7990 }, "escaped": 10, ... },
//       "performance": { "particleStepsPerSecond": 2.1e7, ... }, "settings": { ... } }
#pragma once

#include "slides/analysis/scene_analysis.h"
#include "slides/config/scene.h"
#include "slides/run/stepper.h"

#include <nlohmann/json.hpp>

namespace slides {

struct RunMetrics {
    double wallSeconds = 0;     ///< the whole run, output included
    double steppingSeconds = 0; ///< inside Stepper::step() only
    int threads = 1;
    std::string carrier;                                        ///< CarrierField::describe()
    std::vector<std::string> boundaryNames;                     ///< CarrierField::boundaryNames()
    std::vector<std::pair<std::string, double>> carrierFigures; ///< CarrierField::figures()
    const SceneAnalysis* analysis = nullptr;                    ///< the scene analysis, if run
};

/// Escapes by exit name: the carrier's patches by name, the domain box as "domain".
nlohmann::json escapedThrough(const Stepper& stepper, const std::vector<std::string>& patches);

/// The summary of a finished (or stopped) run.
nlohmann::json runSummary(const Scene& scene, const Stepper& stepper, const RunMetrics& metrics);

/// The scene analysis as JSON: figures, the decision table, the time step and its limits.
nlohmann::json sceneAnalysisJson(const SceneAnalysis& analysis);

/// The scene as JSON, every value in SI units, as used by the run.
nlohmann::json sceneSettings(const Scene& scene);

} // namespace slides
