// Fuzz entry points: what the fuzz targets (tools/fuzz/) feed arbitrary bytes to, shared with
// the regression test that replays every input they once crashed on (tests/fuzz/).
//
// The contract under test: any input either parses or raises the one InputError naming the
// file and line; it never crashes, hangs, reads out of bounds or throws anything else.
#pragma once

#include "slides/carrier/foam_field.h"
#include "slides/carrier/foam_mesh.h"
#include "slides/config/dictionary.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"

#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <unistd.h>

namespace slides::fuzz {

/// A case dictionary (constant/slidesProperties) given as text: parse it and build the Scene.
inline void readDictionaryText(std::string_view text) {
    try {
        const Dictionary dictionary =
            Dictionary::parseString(text, "fuzz/constant/slidesProperties");
        (void)sceneFromDictionary(dictionary, "fuzz");
    } catch (const InputError&) {
        // the expected outcome for a bad input
    }
}

/// An OpenFOAM case (the checked-in box of tests/foam/data/<mesh>) with one of its files
/// replaced by arbitrary bytes: the first byte chooses the file (points, faces, owner,
/// neighbour, boundary or the field 0/C), the rest is its content, plain or gzip-compressed as
/// the rest starts. The mesh is read, then the field, as the OpenFOAM carrier does.
inline void readFoamCaseWithReplacedFile(std::string_view bytes, const std::string& mesh) {
    namespace fs = std::filesystem;
    if (bytes.empty()) return;
    static constexpr std::array<const char*, 6> files{
        "constant/polyMesh/points",    "constant/polyMesh/faces",    "constant/polyMesh/owner",
        "constant/polyMesh/neighbour", "constant/polyMesh/boundary", "0/C"};
    const fs::path original = fs::path(SLIDES_SOURCE_DIR) / "tests" / "foam" / "data" / mesh;
    const fs::path scratch =
        fs::temp_directory_path() / ("slides-fuzz-foam-" + std::to_string(::getpid()));
    fs::remove_all(scratch);
    fs::copy(original, scratch, fs::copy_options::recursive);
    const fs::path replaced =
        scratch / files[static_cast<unsigned char>(bytes.front()) % files.size()];
    const bool gzip = bytes.size() > 2 && bytes[1] == '\x1f' && bytes[2] == '\x8b';
    fs::remove(replaced);
    fs::remove(replaced.string() + ".gz");
    std::ofstream(gzip ? replaced.string() + ".gz" : replaced.string(), std::ios::binary)
        << bytes.substr(1);
    try {
        const FoamMesh foamMesh = readFoamMesh(scratch);
        (void)readFoamVolField<Vec3>(scratch / "0", "C", foamMesh);
    } catch (const InputError&) {
        // the expected outcome for a bad input
    }
    fs::remove_all(scratch);
}

} // namespace slides::fuzz
