// Reads CASE/constant/slidesProperties into a validated Scene.
//
// Every key is checked against the key table (config/scene_keys.h): unknown keys, wrong types,
// out-of-range numbers and inconsistent combinations are InputErrors naming file, line and key.
#pragma once

#include "slides/config/scene.h"

#include <filesystem>
#include <string>

namespace slides {

class Dictionary;

/// The scene of the case directory caseDirectory (reads constant/slidesProperties).
Scene readScene(const std::filesystem::path& caseDirectory);

/// The scene described by an already parsed dictionary (for tests and tools).
Scene sceneFromDictionary(const Dictionary& dictionary, const std::filesystem::path& caseDirectory);

/// The line of the dotted key path in the dictionary file, 0 when it is not there: for errors
/// found once the carrier is known, after the dictionary was read.
int keyLine(const std::filesystem::path& dictionaryFile, const std::string& path);

} // namespace slides
