// Reads CASE/constant/slidesProperties into a validated Scene.
//
// Every key is checked against the key table (config/scene_keys.h): unknown keys, wrong types,
// out-of-range numbers and inconsistent combinations are InputErrors naming file, line and key.
#pragma once

#include "slides/config/scene.h"

#include <filesystem>

namespace slides {

class Dictionary;

/// The scene of the case directory caseDirectory (reads constant/slidesProperties).
Scene readScene(const std::filesystem::path& caseDirectory);

/// The scene described by an already parsed dictionary (for tests and tools).
Scene sceneFromDictionary(const Dictionary& dictionary, const std::filesystem::path& caseDirectory);

} // namespace slides
