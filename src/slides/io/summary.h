// Run summary: CASE/slides/summary.json — counts, arrival statistics, speed and the settings.
//
//     { "particles": { "injected": 8000, "arrived": { "target": 7990 }, "escaped": 10, ... },
//       "performance": { "particleStepsPerSecond": 2.1e7, ... }, "settings": { ... } }
#pragma once

#include "slides/carrier/jet_frame.h"
#include "slides/integrate/injection_settings.h"
#include "slides/io/run_snapshot.h"
#include "slides/surfaces/surface_settings.h"

#include <filesystem>
#include <nlohmann/json.hpp>
#include <span>
#include <string>
#include <utility>
#include <vector>

namespace slides {

struct RunMetrics {
    double wallSeconds = 0;     ///< the whole run, output included
    double steppingSeconds = 0; ///< inside Stepper::step() only
    int threads = 1;
    std::string carrier;                                        ///< CarrierField::describe()
    std::vector<std::string> boundaryNames;                     ///< CarrierField::boundaryNames()
    std::vector<std::pair<std::string, double>> carrierFigures; ///< CarrierField::figures()
};

/// What the summary reports of the resolved scene besides the run's state.
struct SummaryInputs {
    std::filesystem::path caseDirectory;
    long requested = 0; ///< particles.count
    std::span<const Surface> surfaces;
    JetNozzle nozzle;              ///< arrivals' distance from its axis
    bool temperature = false;      ///< particles carry a temperature (heat transfer)
    bool collisions = false;       ///< particle collisions are on
    double stokesResponseTime = 0; ///< at the mean radius [s]
    nlohmann::json sceneAnalysis;  ///< the scene analysis as JSON; null when not run
    nlohmann::json settings;       ///< every setting used, in SI units
    /// The injectors of `injectors {}` and their particle ids; empty: arrivals are not split
    /// by injector.
    std::vector<std::string> injectorNames;
    InjectorIds injectorIds;
};

/// Escapes by exit name: the carrier's patches by name, the domain box as "domain".
nlohmann::json escapedThrough(const RunCounters& counters, const std::vector<std::string>& patches);

/// The summary of a finished (or stopped) run.
nlohmann::json runSummary(const RunSnapshot& snapshot, const SummaryInputs& inputs,
                          const RunMetrics& metrics);

} // namespace slides
