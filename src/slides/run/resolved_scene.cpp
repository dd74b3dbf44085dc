#include "slides/run/resolved_scene.h"

#include "slides/carrier/foam_decomposition.h"
#include "slides/carrier/make_carrier.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/run/injection_check.h"
#include "slides/run/rank_carrier.h"
#include "slides/run/run_limits.h"
#include "slides/surfaces/patch_wall.h"

#include <sstream>

namespace slides {

namespace {

/// Refuses the value of a command-line option where the key it overrides is (its line in the
/// dictionary, 0 when the dictionary leaves the key to its default).
[[noreturn]] void refuseOverride(const Scene& scene, const std::string& key,
                                 const std::string& option, double value, const std::string& what) {
    std::ostringstream message;
    message << option << " " << value << " on the command line " << what;
    throw InputError(scene.dictionaryFile.string(), keyLine(scene.dictionaryFile, key), key,
                     message.str());
}

void applyOverrides(const SceneOverrides& overrides, Scene& scene) {
    if (overrides.endTime) {
        if (!(*overrides.endTime > 0))
            refuseOverride(scene, "time.endTime", "--end-time", *overrides.endTime,
                           "must be positive");
        scene.time.endTime = *overrides.endTime;
    }
    if (overrides.dt) {
        if (!(*overrides.dt > 0))
            refuseOverride(scene, "time.dt", "--dt", *overrides.dt, "must be positive");
        scene.time.dt = *overrides.dt;
    }
    if (overrides.time) {
        if (scene.carrier.type != CarrierType::foamField)
            throw InputError("command line", 0, "--time",
                             "only an OpenFOAM carrier (foamField) has time directories");
        scene.carrier.foamTime = *overrides.time;
    }
    if (scene.time.dt > scene.time.endTime) {
        std::ostringstream dt, endTime;
        dt << "is longer than time.endTime " << scene.time.endTime << " s";
        endTime << "is shorter than time.dt " << scene.time.dt << " s";
        if (overrides.dt) refuseOverride(scene, "time.dt", "--dt", scene.time.dt, dt.str());
        refuseOverride(scene, "time.endTime", "--end-time", scene.time.endTime, endTime.str());
    }
}

} // namespace

std::unique_ptr<CarrierField> carrierOf(const Scene& scene) {
    return makeCarrier(scene.carrier, scene.nozzle, scene.fluid.temperature,
                       scene.physics.carrierNeeds(), scene.caseDirectory, scene.dictionaryFile);
}

ResolvedScene resolveScene(const std::filesystem::path& caseDirectory,
                           const SceneOverrides& overrides, const RankCommunicator& ranks) {
    Scene scene = readScene(caseDirectory);
    applyOverrides(overrides, scene);
    const bool foam = scene.carrier.type == CarrierType::foamField;
    if (ranks.parallel() && !foam)
        throw InputError(scene.dictionaryFile.string(), 0, "carrier.type",
                         "parallel runs (-parallel) need a decomposed OpenFOAM case, carrier type "
                         "foamField, so far");
    if (foam && !ranks.parallel()) requireDecompositionFits(caseDirectory, false, 1);
    if (ranks.parallel()) // no ghosts across ranks yet: `auto` leaves collisions off
        for (AutomaticTerm& automatic : scene.physics.automaticTerms)
            if (automatic.term == PhysicsTerm::collisions && automatic.unavailable.empty())
                automatic.unavailable = "not supported in parallel runs yet";
    std::unique_ptr<const CarrierField> carrier =
        ranks.parallel()
            ? std::make_unique<RankCarrier>(
                  caseDirectory,
                  FoamCarrierSettings{scene.carrier.foamTime, scene.carrier.interpolation,
                                      scene.carrier.latticeSpacing, std::nullopt /* no series */},
                  ranks)
            : carrierOf(scene);
    if (scene.domainFromCarrier) scene.domain = carrier->bounds().value();
    requireInjectionInside(scene, *carrier);
    scene.surfaces = placePatchSurfaces(scene.surfaces, *carrier, scene.dictionaryFile);
    SceneAnalysis analysis = analyseScene(scene, *carrier);
    applyAnalysis(analysis, scene);
    requireRunWithinLimits(scene);
    return {std::move(scene), std::move(carrier), std::move(analysis)};
}

} // namespace slides
