#include "slides/config/scene_json.h"

#include "slides/core/name_table.h"

#include <cmath>
#include <set>

namespace slides {

namespace {

nlohmann::json vec(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json material(const MaterialSettings& m) {
    return {{"bulkModulus", m.bulkModulus},
            {"shearModulus", m.shearModulus},
            {"yieldStress", m.yieldStress},
            {"surfaceEnergy", m.surfaceEnergy}};
}

nlohmann::json radiusDistribution(const RadiusDistribution& radius) {
    return {{"type", nameOf(radiusDistributionNames(), radius.kind)},
            {"weighting", nameOf(sizeWeightingNames(), radius.weighting)},
            {"meanRadius", radius.meanRadius()},
            {"minimum", radius.minimum},
            {"maximum", std::isfinite(radius.maximum) ? nlohmann::json(radius.maximum) : nullptr}};
}

nlohmann::json injectorSettings(const InjectorSettings& injector) {
    nlohmann::json entry = {{"model", nameOf(injectionModelNames(), injector.model)},
                            {"firstId", injector.firstId},
                            {"count", injector.count},
                            {"startTime", injector.startTime},
                            {"centre", vec(injector.nozzle.centre)},
                            {"axis", vec(injector.nozzle.axis)},
                            {"radius", injector.nozzle.radius}};
    if (injector.model == InjectionModel::file) {
        const ParticleFileSettings& file = injector.file;
        entry["file"] = {{"format", nameOf(particleFileFormatNames(), file.format)}};
        if (file.format == ParticleFileFormat::particlesH5)
            entry["file"]["source"] = nameOf(previousRunSourceNames(), file.source);
        if (file.format == ParticleFileFormat::particlesH5 &&
            file.source == PreviousRunSource::frame)
            entry["file"]["frame"] = file.frame;
        if (file.format == ParticleFileFormat::foamPositions) {
            entry["file"]["velocity"] = vec(file.velocity);
            entry["radiusDistribution"] = radiusDistribution(injector.radius);
        }
        return entry;
    }
    if (injector.model == InjectionModel::ensemble) {
        PackedEnsemble packed;
        for (const ParticleRow& row : injector.rows) packed.radii.push_back(row.radius);
        packed.centres.resize(packed.radii.size());
        const PackingRegion& region = injector.ensemble.region;
        entry["ensemble"] = {{"method", nameOf(packingMethodNames(), injector.ensemble.method)},
                             {"shape", nameOf(packingShapeNames(), region.shape)},
                             {"volumeFraction", packed.volumeFraction(region.volume())}};
        return entry;
    }
    entry["mode"] = nameOf(injectionModeNames(), injector.injection.mode);
    entry["rate"] = injector.injection.rate;
    entry["reinjectEscaped"] = injector.injection.reinjectEscaped;
    entry["radiusDistribution"] = radiusDistribution(injector.radius);
    if (injector.model == InjectionModel::disc)
        entry["crossSpanSpeed"] = injector.injection.crossSpanSpeed;
    if (injector.model == InjectionModel::cone)
        entry["cone"] = {{"innerHalfAngle", injector.cone.innerHalfAngle},
                         {"outerHalfAngle", injector.cone.outerHalfAngle},
                         {"speed", injector.cone.speed},
                         {"speedStandardDeviation", injector.cone.speedDeviation}};
    if (injector.model == InjectionModel::patch)
        entry["patch"] = {{"patch", injector.patch.name},
                          {"velocity", injector.patch.velocity ? vec(*injector.patch.velocity)
                                                               : nlohmann::json("(U·n) n")}};
    return entry;
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
    if (carrier.pulsation)
        settings["carrier"]["pulsation"] = {{"amplitude", carrier.pulsation->amplitude},
                                            {"frequency", carrier.pulsation->frequency}};
    if (carrier.type == CarrierType::oscillatingGas)
        settings["carrier"]["oscillatingGas"] = {{"amplitude", vec(carrier.oscillationAmplitude)},
                                                 {"frequency", carrier.oscillationFrequency}};
    if (carrier.type == CarrierType::taylorGreenVortex)
        settings["carrier"]["taylorGreenVortex"] = {{"velocity", carrier.vortexVelocity},
                                                    {"wavelength", carrier.vortexWavelength}};
    if (carrier.type == CarrierType::planePoiseuille)
        settings["carrier"]["planePoiseuille"] = {
            {"centrelineVelocity", carrier.centrelineVelocity},
            {"halfWidth", carrier.channelHalfWidth}};
    if (carrier.foamSeries) {
        auto& series = settings["carrier"]["series"];
        series["times"] = carrier.foamSeries->range
                              ? nlohmann::json::array({carrier.foamSeries->range->first,
                                                       carrier.foamSeries->range->second})
                              : nlohmann::json("all");
        if (carrier.foamSeries->cycle) series["cycle"] = *carrier.foamSeries->cycle;
        series["readAhead"] = carrier.foamSeries->readAhead;
    }
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
    // Injectors whose particles differ: each species, and each injector's.
    for (const ParticleSpecies& species : scene.particles.species)
        settings["particles"]["species"].push_back({{"density", species.density},
                                                    {"material", material(species.material)},
                                                    {"specificHeat", species.specificHeat},
                                                    {"susceptibility", species.susceptibility}});
    settings["injection"] = {{"mode", nameOf(injectionModeNames(), scene.injection.mode)},
                             {"rate", scene.injection.rate},
                             {"crossSpanSpeed", scene.injection.crossSpanSpeed},
                             {"reinjectEscaped", scene.injection.reinjectEscaped},
                             {"seed", scene.injection.seed}};
    for (const InjectorSettings& injector : scene.injectors) {
        settings["injectors"][injector.name] = injectorSettings(injector);
        if (scene.particles.alike()) continue;
        // Its species; those of its rows where they differ (a file's densities).
        const auto species = scene.particles.speciesOfParticles(
            static_cast<std::size_t>(&injector - scene.injectors.data()));
        settings["injectors"][injector.name]["species"] =
            species.size() == 1
                ? nlohmann::json(species.front())
                : nlohmann::json(std::set<std::int32_t>(species.begin(), species.end()));
    }
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
        {"faxen", scene.physics.faxen},
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
    const ElectromagneticSettings& charged = scene.physics.electromagnetic;
    settings["physics"]["electromagnetic"] = {
        {"model", nameOf(electromagneticModelNames(), charged.model)},
        {"E", vec(charged.electricField)},
        {"B", vec(charged.magneticField)},
        {"charge",
         {{"model", nameOf(chargeModelNames(), charged.charge)},
          {"value", charged.chargeValue},
          {"oppositeSignFraction", charged.oppositeSignFraction}}},
        {"coulomb",
         {{"model", nameOf(coulombModelNames(), charged.coulomb.model)},
          {"cutoff", charged.coulomb.cutoff},
          {"permittivity", charged.coulomb.permittivity}}},
        {"magnetisation",
         {{"model", nameOf(magnetisationModelNames(), charged.magnetisation)},
          {"susceptibility", scene.particles.susceptibility}}}};
    for (const CurrentLoop& coil : charged.coils)
        settings["physics"]["electromagnetic"]["coils"][coil.name] = {{"centre", vec(coil.centre)},
                                                                      {"axis", vec(coil.axis)},
                                                                      {"radius", coil.radius},
                                                                      {"current", coil.current}};
    settings["time"] = {{"dt", scene.time.dt},
                        {"endTime", scene.time.endTime},
                        {"stopWhenAllDone", scene.time.stopWhenAllDone},
                        {"integrator", nameOf(integratorNames(), scene.time.integrator)},
                        {"tolerance", scene.time.tolerance}};
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
    for (const auto& plane : scene.surfaces) {
        if (plane.interaction != SurfaceInteraction::erode) continue;
        const ErosionSettings& layer = plane.erosion;
        settings["surfaces"][plane.name]["erosion"] = {
            {"thickness", layer.thickness}, {"width", layer.width},
            {"porosity", layer.porosity},   {"boundWeight", layer.boundWeight},
            {"threshold", layer.threshold}, {"cells", layer.cells}};
    }
    settings["domain"] = {{"min", vec(scene.domain.min)}, {"max", vec(scene.domain.max)}};
    std::vector<std::string_view> fields;
    for (const auto& field : particleFieldNames())
        if (scene.output.fields.contains(field.value)) fields.push_back(field.name);
    settings["output"] = {{"interval", scene.output.interval},
                          {"carrierResolution", scene.output.carrierResolution},
                          {"fields", fields}};
    return settings;
}

} // namespace slides
