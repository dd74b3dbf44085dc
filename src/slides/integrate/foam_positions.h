// Foam positions: the particle positions of an OpenFOAM list file, as manualInjection's
// `positionsFile` (constant/kinematicCloudPositions) or a cloud's `positions` file gives them.
//
// Reference: OpenFOAM v1912, ManualInjection.C (a vectorIOField) and particleIO.C
// (writePosition: a position then its cell label). A FoamFile header, then a list with or
// without its length; an entry is a position, optionally followed by labels (the cell, and in
// some versions its tetFace and tetPt), which are left out: the carrier locates the particles
// itself. Binary vectorField files are read as well.
//
//     FoamFile { version 2.0; format ascii; class vectorField; object kinematicCloudPositions; }
//     3
//     (
//     (0.001 0 0)
//     (0.002 0.0005 0) 117
//     (0.003 -0.0005 0) 117 402 1
//     )
#pragma once

#include "slides/core/vector.h"

#include <filesystem>
#include <string>
#include <vector>

namespace slides {

/// The positions of the list in file [m]; a malformed entry or a length that differs from the
/// entries throws InputError naming file:line and key (the dictionary key that names the file).
std::vector<Vec3> readFoamPositions(const std::filesystem::path& file, const std::string& key);

} // namespace slides
