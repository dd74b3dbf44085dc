// Scene as JSON: every setting of a resolved scene in SI units, each choice by its family's
// name table — the "settings" of summary.json.
//
//     "settings": { "physics": { "drag": "haiderLevenspiel", ... }, "time": { "dt": 1e-05 } }
#pragma once

#include "slides/config/scene.h"

#include <nlohmann/json.hpp>

namespace slides {

/// The scene as JSON, every value in SI units, as used by the run.
nlohmann::json sceneSettings(const Scene& scene);

} // namespace slides
