// Resolved scene: the one step that turns a case into the immutable scene a run uses.
//
//   read constant/slidesProperties (config/scene_reader.h) → command-line overrides → build
//   the carrier (carrier/make_carrier.h) → the domain from the carrier's bounds when none is
//   given → wall patches placed as surfaces (surfaces/patch_wall.h) → the scene analysis
//   (analysis/scene_analysis.h) → its `auto` decisions and default dt applied.
// Nothing changes the result afterwards: the stepper, the writers and the summary take it
// const, and the summary reports exactly it.
#pragma once

#include "slides/analysis/scene_analysis.h"
#include "slides/carrier/carrier_field.h"
#include "slides/config/scene.h"
#include "slides/run/rank_communicator.h"
#include "slides/run/run_options.h"

#include <filesystem>
#include <memory>

namespace slides {

struct ResolvedScene {
    Scene scene;                                 ///< every setting, `auto` decided
    std::unique_ptr<const CarrierField> carrier; ///< the gas the particles move in
    SceneAnalysis analysis;                      ///< what decided the `auto` terms and dt
};

/// The scene's carrier (carrier/make_carrier.h), from the parts of the scene it takes.
std::unique_ptr<CarrierField> carrierOf(const Scene& scene);

/// Resolves the case in caseDirectory with the command line's overrides. Throws InputError
/// naming file, line and key for bad input, before anything is written. A parallel run's ranks
/// each read their processor part of a decomposed case (run/rank_carrier.h) and resolve the
/// same scene (the pilots of the scene analysis run on every rank alike).
ResolvedScene resolveScene(const std::filesystem::path& caseDirectory,
                           const SceneOverrides& overrides, const RankCommunicator& ranks = {});

} // namespace slides
