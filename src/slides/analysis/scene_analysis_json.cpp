#include "slides/analysis/scene_analysis_json.h"

#include <cmath>

namespace slides {

namespace {

/// A number, or null where it is not defined (NaN), as JSON has no NaN.
nlohmann::json numberOrNull(double value) {
    if (std::isnan(value)) return nullptr;
    return value;
}

} // namespace

nlohmann::json sceneAnalysisJson(const SceneAnalysis& analysis) {
    const SceneFigures& f = analysis.figures;
    nlohmann::json result;
    result["pilot"] = {{"particles", analysis.pilot.particles},
                       {"steps", analysis.pilot.steps},
                       {"dt", analysis.pilot.dt},
                       {"unfinished", analysis.pilot.unfinished}};
    result["figures"] = {
        {"referenceSpeed", f.referenceSpeed},
        {"densityRatio", f.densityRatio},
        {"stokesNumber", {numberOrNull(f.stokesNumberMin), numberOrNull(f.stokesNumberMax)}},
        {"reynoldsNumber", {f.reynoldsMin, f.reynoldsMax}},
        {"responseTime", {numberOrNull(f.responseTimeMin), numberOrNull(f.responseTimeMax)}},
        {"flightTime", f.flightTime},
        {"volumeFractionNozzle", f.volumeFractionNozzle},
        {"volumeFractionMax", f.volumeFractionMax},
        {"collisionsPerParticle", f.collisionsPerParticle},
        {"biotNumber", numberOrNull(f.biotMax)}};
    result["threshold"] = analysis.threshold;
    for (const TermDecision& d : analysis.terms)
        result["terms"].push_back({{"term", physicsTermRow(d.term).name},
                                   {"effect", d.effect},
                                   {"measure", d.measure},
                                   {"peakForceToDrag", numberOrNull(d.peakToDrag)},
                                   {"automatic", d.automatic},
                                   {"decision", d.on ? "on" : "off"},
                                   {"reason", d.reason}});
    result["timeStep"] = {{"suggested", analysis.suggestedTimeStep},
                          {"limitedBy", analysis.timeStepLimitedBy},
                          {"given", analysis.timeStepGiven}};
    for (const TimeStepLimit& limit : analysis.timeStepLimits)
        result["timeStep"]["limits"][limit.name] = limit.value;
    result["warnings"] = analysis.warnings;
    return result;
}

} // namespace slides
