// FoamMesh: an OpenFOAM polyMesh (points, faces, owner, neighbour, boundary) and its geometry.
//
// Reference: OpenFOAM v1912 constant/polyMesh format (User Guide 5.1 "Mesh description"); face
// and cell centres as primitiveMeshFaceCentresAndAreas.C / primitiveMeshCellCentresAndVols.C
// (area-weighted triangle fan about the point average; volume-weighted pyramids about the
// average of the face centres), so the cell centres agree with OpenFOAM's C to round-off.
//
//     constant/polyMesh/{points,faces,owner,neighbour,boundary}[.gz], ascii or binary
//     processor<N>/constant/polyMesh likewise, with `processor` patches (neighbProcNo)
#pragma once

#include "slides/core/vector.h"

#include <cstdint>
#include <filesystem>
#include <span>
#include <string>
#include <vector>

namespace slides {

/// processor: the faces a decomposed case shares with the part of rank neighbourRank (its face i
/// is face i of the matching patch there); neither a wall nor an exit.
enum class PatchType { patch, wall, symmetry, wedge, empty, processor };

struct FoamPatch {
    std::string name;
    PatchType type = PatchType::patch;
    int start = 0;          ///< first face
    int size = 0;           ///< number of faces
    int neighbourRank = -1; ///< processor patch: neighbProcNo
};

struct FoamMesh {
    std::vector<Vec3> points;
    std::vector<int> faceOffsets; ///< face f holds facePoints[faceOffsets[f] .. faceOffsets[f+1])
    std::vector<int> facePoints;
    std::vector<int> owner;     ///< per face
    std::vector<int> neighbour; ///< per internal face
    std::vector<FoamPatch> patches;
    int cellCount = 0;

    // Derived geometry.
    std::vector<Vec3> faceCentres;
    std::vector<Vec3> faceAreas; ///< area-weighted normals, out of the owner
    std::vector<Vec3> cellCentres;
    std::vector<double> cellVolumes;
    std::vector<int> cellFaceOffsets; ///< faces of cell c: cellFaces[cellFaceOffsets[c] ..]
    std::vector<int> cellFaces;
    std::vector<int> facePatch; ///< patch index of each boundary face, -1 for internal faces
    Vec3 boundsMin = Vec3::Zero();
    Vec3 boundsMax = Vec3::Zero();

    int faceCount() const { return static_cast<int>(owner.size()); }
    int internalFaceCount() const { return static_cast<int>(neighbour.size()); }
    std::span<const int> pointsOf(int face) const {
        return {facePoints.data() + faceOffsets[face],
                static_cast<std::size_t>(faceOffsets[face + 1] - faceOffsets[face])};
    }
    std::span<const int> facesOf(int cell) const {
        return {cellFaces.data() + cellFaceOffsets[cell],
                static_cast<std::size_t>(cellFaceOffsets[cell + 1] - cellFaceOffsets[cell])};
    }
    /// The cell on the other side of face from cell, -1 at the boundary.
    int across(int face, int cell) const {
        if (face >= internalFaceCount()) return -1;
        return owner[face] == cell ? neighbour[face] : owner[face];
    }

    /// Fills the derived geometry from points, faces, owner, neighbour and patches.
    void computeGeometry();
};

/// Reads CASE/constant/polyMesh/boundary alone (a decomposed case without the whole mesh:
/// processor0's, its processor patches left out); InputError naming the file on bad content.
std::vector<FoamPatch> readFoamBoundary(const std::filesystem::path& caseDirectory);

/// Reads CASE/constant/polyMesh; InputError naming the file on bad or inconsistent content.
FoamMesh readFoamMesh(const std::filesystem::path& caseDirectory);

} // namespace slides
