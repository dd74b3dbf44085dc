#include "slides/io/summary.h"

#include "slides/core/name_table.h"
#include "slides/integrate/mean_response_time.h"
#include "slides/surfaces/deposit_metrics.h"

#include <cmath>

namespace slides {

namespace {

nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json material(const MaterialSettings& m) {
    return {{"bulkModulus", m.bulkModulus},
            {"shearModulus", m.shearModulus},
            {"yieldStress", m.yieldStress},
            {"surfaceEnergy", m.surfaceEnergy}};
}

/// Mean, standard deviation, rms and extremes of one quantity over the arrivals at one
/// surface (two passes, so the deviation does not cancel catastrophically).
nlohmann::json statistics(const std::vector<double>& values) {
    if (values.empty()) return nullptr;
    const double n = static_cast<double>(values.size());
    double sum = 0, low = values.front(), high = values.front();
    for (double value : values) {
        sum += value;
        low = std::min(low, value);
        high = std::max(high, value);
    }
    const double mean = sum / n;
    double deviations = 0;
    for (double value : values) deviations += (value - mean) * (value - mean);
    const double variance = deviations / n;
    return {{"mean", mean},
            {"standardDeviation", std::sqrt(variance)},
            {"rms", std::sqrt(variance + mean * mean)},
            {"min", low},
            {"max", high}};
}

nlohmann::json arrivalsAt(const Scene& scene, const Stepper& stepper, int surface) {
    const Surface& plane = scene.surfaces[static_cast<std::size_t>(surface)];
    std::vector<double> impactSpeed, normalSpeed, distanceFromAxis, time, temperature;
    for (const auto& arrival : stepper.arrivals()) {
        if (arrival.surface != surface) continue;
        impactSpeed.push_back(arrival.velocity.norm());
        normalSpeed.push_back(-arrival.velocity.dot(plane.normal));
        const Vec3 fromNozzle = arrival.position - scene.nozzle.centre;
        distanceFromAxis.push_back(
            (fromNozzle - fromNozzle.dot(scene.nozzle.axis) * scene.nozzle.axis).norm());
        time.push_back(arrival.time);
        temperature.push_back(arrival.temperature);
    }
    nlohmann::json result = {{"count", impactSpeed.size()},
                             {"impactSpeed", statistics(impactSpeed)},
                             {"impactNormalSpeed", statistics(normalSpeed)},
                             {"distanceFromAxis", statistics(distanceFromAxis)},
                             {"arrivalTime", statistics(time)}};
    if (scene.physics.heatTransfer != HeatTransferModel::none)
        result["temperature"] = statistics(temperature);
    return result;
}

} // namespace

nlohmann::json sceneSettings(const Scene& scene) {
    nlohmann::json settings;
    settings["dictionary"] = scene.dictionaryFile.string();
    settings["fluid"] = {{"density", scene.fluid.density},
                         {"kinematicViscosity", scene.fluid.kinematicViscosity},
                         {"temperature", scene.fluid.temperature}};
    settings["nozzle"] = {{"centre", vec(scene.nozzle.centre)},
                          {"axis", vec(scene.nozzle.axis)},
                          {"radius", scene.nozzle.radius},
                          {"crossSpanDirection", vec(scene.nozzle.crossSpanDirection)}};
    const CarrierSettings& carrier = scene.carrier;
    settings["carrier"] = {{"type", nameOf(carrierTypeNames(), carrier.type)},
                           {"profile", nameOf(jetGeometryNames(), carrier.profile)},
                           {"nozzleVelocity", carrier.nozzleVelocity},
                           {"coreLength", carrier.coreLength},
                           {"viscosity", carrier.viscosity}};
    if (carrier.turbulence)
        settings["carrier"]["turbulence"] = {
            {"scaling", nameOf(turbulenceScalingNames(), carrier.turbulence->scaling)},
            {"intensity", carrier.turbulence->intensity},
            {"lengthScale", carrier.turbulence->lengthScale},
            {"lengthScaleToHalfWidth", carrier.turbulence->lengthScaleToHalfWidth}};
    const RadiusDistribution& radius = scene.particles.radius;
    settings["particles"] = {
        {"count", scene.particles.count},
        {"density", scene.particles.density},
        {"radiusDistribution",
         {{"type", nameOf(radiusDistributionNames(), radius.kind)},
          {"meanRadius", radius.meanRadius()},
          {"minimum", radius.minimum},
          {"maximum", std::isfinite(radius.maximum) ? nlohmann::json(radius.maximum) : nullptr}}},
        {"material", material(scene.particles.material)}};
    settings["injection"] = {{"mode", nameOf(injectionModeNames(), scene.injection.mode)},
                             {"rate", scene.injection.rate},
                             {"crossSpanSpeed", scene.injection.crossSpanSpeed},
                             {"seed", scene.injection.seed}};
    settings["physics"] = {
        {"drag", nameOf(dragModelNames(), scene.physics.drag)},
        {"gravity", vec(scene.physics.gravity)},
        {"buoyancy", scene.physics.buoyancy},
        {"history",
         {{"model", nameOf(historyModelNames(), scene.physics.history)},
          {"accuracy", scene.physics.historyAccuracy}}},
        {"addedMass", scene.physics.addedMass},
        {"pressureGradient", scene.physics.pressureGradient},
        {"lift", nameOf(liftModelNames(), scene.physics.lift)},
        {"spin", scene.physics.spin},
        {"spinHistory", scene.physics.spinHistory},
        {"autoThreshold", scene.physics.autoThreshold},
        {"dispersion",
         {{"model", nameOf(dispersionModelNames(), scene.physics.dispersion)},
          {"Cmu", scene.physics.dispersionConstants.Cmu},
          {"turbulentSchmidtNumber", scene.physics.dispersionConstants.turbulentSchmidtNumber}}},
        {"heatTransfer",
         {{"model", nameOf(heatTransferModelNames(), scene.physics.heatTransfer)},
          {"fluidThermalConductivity", scene.fluid.thermalConductivity},
          {"fluidSpecificHeat", scene.fluid.specificHeat},
          {"particleSpecificHeat", scene.particles.specificHeat},
          {"injectionTemperature", scene.particles.injectionTemperature}}}};
    settings["time"] = {{"dt", scene.time.dt},
                        {"endTime", scene.time.endTime},
                        {"stopWhenAllDone", scene.time.stopWhenAllDone},
                        {"integrator", nameOf(integratorNames(), scene.time.integrator)}};
    const CollisionSettings& collisions = scene.collisions;
    settings["collisions"] = {
        {"model", nameOf(collisionModelNames(), collisions.model)},
        {"restitution",
         {{"model", nameOf(restitutionModelNames(), collisions.restitution.model)},
          {"coefficient", collisions.restitution.coefficient},
          {"yieldPressureFactor", collisions.restitution.yieldPressureFactor}}},
        {"friction",
         {{"static", collisions.friction.staticCoefficient},
          {"dynamic", collisions.friction.dynamicCoefficient}}}};
    settings["deposition"] = {{"adhesion", nameOf(adhesionModelNames(), scene.deposition.model)},
                              {"adhesionFactor", scene.deposition.factor},
                              {"hamakerConstant", scene.deposition.hamakerConstant},
                              {"contactSeparation", scene.deposition.contactSeparation}};
    for (const auto& plane : scene.surfaces)
        settings["surfaces"][plane.name] = {
            {"type", "plane"},
            {"point", vec(plane.point)},
            {"normal", vec(plane.normal)},
            {"interaction", nameOf(surfaceInteractionNames(), plane.interaction)},
            {"material", material(plane.material)}};
    settings["domain"] = {{"min", vec(scene.domain.min)}, {"max", vec(scene.domain.max)}};
    std::vector<std::string_view> fields;
    for (const auto& field : particleFieldNames())
        if (scene.output.fields.contains(field.value)) fields.push_back(field.name);
    settings["output"] = {{"interval", scene.output.interval},
                          {"carrierResolution", scene.output.carrierResolution},
                          {"fields", fields}};
    return settings;
}

nlohmann::json escapedThrough(const Stepper& stepper, const std::vector<std::string>& patches) {
    nlohmann::json counts = nlohmann::json::object();
    const auto& exits = stepper.escapedThrough();
    for (std::size_t exit = 0; exit < exits.size(); ++exit)
        if (exits[exit] > 0)
            counts[exit == 0 || exit > patches.size() ? "domain" : patches[exit - 1]] = exits[exit];
    return counts;
}

nlohmann::json runSummary(const Scene& scene, const Stepper& stepper, const RunMetrics& metrics) {
    nlohmann::json summary;
    summary["slidesTrack"] = SLIDES_VERSION;
    summary["case"] = scene.caseDirectory.string();
    summary["carrier"] = metrics.carrier;
    for (const auto& [name, value] : metrics.carrierFigures)
        summary["carrierFigures"][name] = value;

    nlohmann::json arrived = nlohmann::json::object();
    nlohmann::json arrivals = nlohmann::json::object();
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        arrivals[scene.surfaces[s].name] = arrivalsAt(scene, stepper, static_cast<int>(s));
        arrived[scene.surfaces[s].name] = arrivals[scene.surfaces[s].name]["count"];
    }
    summary["particles"] = {{"requested", scene.particles.count},
                            {"injected", stepper.injected()},
                            {"arrived", arrived},
                            {"escaped", stepper.escaped()},
                            {"escapedThrough", escapedThrough(stepper, metrics.boundaryNames)},
                            {"active", stepper.cloud().size()}};
    summary["arrivals"] = arrivals;
    if (stepper.collisions() > 0 || scene.collisions.model != CollisionModel::none)
        summary["collisions"] = {{"particlePairs", stepper.collisions()}};
    for (std::size_t s = 0; s < scene.surfaces.size(); ++s) {
        const Surface& plane = scene.surfaces[s];
        if (plane.interaction == SurfaceInteraction::absorb) continue;
        const std::uint64_t rebounds = stepper.surfaceImpacts().rebounds()[s];
        summary["rebounds"][plane.name] = rebounds;
        if (plane.interaction != SurfaceInteraction::deposit) continue;
        const DepositMetrics deposit =
            depositMetrics(plane, static_cast<int>(s), stepper.arrivals(), stepper.injected());
        summary["deposition"][plane.name] = {
            {"stuck", deposit.stuck},
            {"depositedFraction", deposit.fraction},
            {"depositHeight", deposit.height},
            {"depositHeightToNozzleRadius", deposit.height / scene.nozzle.radius},
            {"meanRadius", deposit.meanRadius},
            {"lowestCentre", deposit.lowestCentre},
            {"highestCentre", deposit.highestCentre},
            {"note", "Eq. 5.12: n_dep = stuck / injected, h_dep = (x_max + R_av) - (x_min - "
                     "R_av), x = centre height above the plane"}};
    }

    summary["responseTime"] = {{"stokes", meanStokesResponseTime(scene.particles, scene.fluid)},
                               {"note", "tau_St = 2 rho_p R^2 / (9 rho_f nu) at the mean radius"}};
    summary["time"] = {{"end", stepper.time()}, {"steps", stepper.steps()}};
    const double particleSteps = static_cast<double>(stepper.particleSteps());
    // Particle-steps per second of the stepping alone (output time is reported beside it).
    summary["performance"] = {
        {"wallSeconds", metrics.wallSeconds},
        {"steppingSeconds", metrics.steppingSeconds},
        {"threads", metrics.threads},
        {"particleSteps", stepper.particleSteps()},
        {"particleStepsPerSecond",
         metrics.steppingSeconds > 0 ? particleSteps / metrics.steppingSeconds : 0.0}};
    // A cost, not a result: a restarted run builds its list once more.
    if (const SoftSphereCollisions* softSpheres = stepper.softSpheres())
        summary["performance"]["neighbourListBuilds"] = softSpheres->listBuilds();
    if (metrics.analysis) summary["sceneAnalysis"] = sceneAnalysisJson(*metrics.analysis);
    summary["settings"] = sceneSettings(scene);
    return summary;
}

/// A number, or null where it is not defined (NaN), as JSON has no NaN.
nlohmann::json numberOrNull(double value) {
    if (std::isnan(value)) return nullptr;
    return value;
}

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
