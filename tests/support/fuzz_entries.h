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
#include "slides/io/checkpoint.h"

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <unistd.h>
#include <vector>

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

/// The run a checkpoint seed belongs to (tests/fuzz/regressions/checkpoint/): a version and a
/// dictionary hash no real run has, so that the seeds do not change with the program's version.
inline const RunFingerprint checkpointFingerprint{"fuzz", 0, 1e-5};

/// A small state with every array a checkpoint can hold: 5 particles with model state (3 a
/// particle), eddies, temperatures, spins and contact loads; 2 arrivals, 2 springs, 3 frames.
inline void writeSeedCheckpoint(const std::filesystem::path& directory) {
    ParticleCloud cloud;
    cloud.stateWidth = 3;
    for (int i = 0; i < 5; ++i) {
        cloud.add(static_cast<ParticleId>(10 + i), Vec3(0.01 * i, 1e-3, -2e-3),
                  Vec3(20 + i, 0.5, -0.25), 40e-6 + 1e-6 * i);
        cloud.carrierLocation.push_back(-1);
        cloud.eddy.push_back({Vec3(0.1, -0.2, 0.3), 1e-4, 2e-5, static_cast<std::uint32_t>(i)});
        cloud.temperature.push_back(300 + i);
        cloud.angularVelocity.push_back(Vec3(1, 2, 3) * i);
        cloud.contactForce.push_back(Vec3(1e-6, 0, 0));
        cloud.contactTorque.push_back(Vec3(0, 0, 1e-9));
        for (int k = 0; k < 3; ++k) cloud.modelState[3 * i + k] = 0.5 * i + k; // add() sized it
    }
    const std::vector<Arrival> arrivals{
        {3, 0, 2.5e-3, Vec3(0.06, 1e-3, 0), Vec3(18, 1, 0), 40e-6, 350, Vec3::Zero()},
        {7, 0, 2.7e-3, Vec3(0.06, -2e-3, 1e-3), Vec3(17, -1, 0.5), 41e-6, 351, Vec3(0, 0, 5)}};
    const RunSnapshot snapshot{
        {3e-3, 300, 12, 1, 2400, {0, 1}, 4, {2}, {}}, cloud, arrivals, {}, {}};
    const SpringColumns springs{
        {10, 11}, {12, 13}, {Vec3(1e-7, 0, 0), Vec3(0, -1e-7, 0)}, {2e-7, 3e-7}};
    const std::vector<FrameRecord> frames{{0, 0}, {1e-3, 5}, {2e-3, 9}};
    writeCheckpoint(directory, snapshot, &springs, frames, 3.5e-3, {1.5, 1.25},
                    checkpointFingerprint);
}

/// A checkpoint.h5 given as bytes, read as a restart reads it. What it accepts must be a state
/// a run can continue from: positions, velocities and radii finite, one entry a particle.
inline void readCheckpointBytes(std::string_view bytes) {
    namespace fs = std::filesystem;
    const fs::path scratch =
        fs::temp_directory_path() / ("slides-fuzz-checkpoint-" + std::to_string(::getpid()));
    fs::remove_all(scratch);
    fs::create_directories(scratch);
    std::ofstream(scratch / checkpointFileName, std::ios::binary) << bytes;
    try {
        const CheckpointState state = readCheckpoint(scratch, checkpointFingerprint);
        const ParticleCloud& cloud = state.cloud;
        for (std::size_t i = 0; i < cloud.size(); ++i)
            if (!cloud.position.at(i).allFinite() || !cloud.velocity.at(i).allFinite() ||
                !std::isfinite(cloud.radius.at(i)))
                throw std::logic_error("a checkpoint with a non-finite particle was accepted");
    } catch (const InputError&) {
        // the expected outcome for a bad input
    }
    fs::remove_all(scratch);
}

} // namespace slides::fuzz
