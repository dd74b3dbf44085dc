// FoamLocator: the cell and tetrahedron of a polyhedral mesh holding a point.
//
// Each cell is split into tetrahedra (cell centre, face point-average, two consecutive face
// points), as OpenFOAM's tetDecomposition splits it about the cell centre; neighbouring cells
// share the face triangles, so the tetrahedra tile the mesh. Each tetrahedron has one index,
// 2 × (its face point slot in mesh.facePoints) + (0 in the face's owner, 1 in its neighbour):
// below 2³¹ up to 2³⁰ face point slots (~2.7e8 faces of four points), so a particle keeps its
// tetrahedron between steps in one int32. locateFrom() walks from a start tetrahedron across
// the face opposite the most negative barycentric weight (a visibility walk: no step while the
// point stays in its tetrahedron, O(1) steps when the start is the particle's previous
// tetrahedron); locate() starts from a cell, in its tetrahedron that faces the point. Without
// a start, or when the walk reaches the boundary, a uniform bin grid over the cells' bounding
// boxes gives the cell with the nearest centre to walk from, and when that walk leaves the mesh
// (a concave boundary) the bin's cells whose boxes hold the point are tested. A point in no
// cell is outside, with the patch the walk left through.
//
//     FoamLocator locator(mesh);  TetLocation at = locator.locateFrom(x, previousTet);
#pragma once

#include "slides/carrier/foam_mesh.h"

#include <array>
#include <optional>

namespace slides {

/// A point inside tetrahedron (cell, face, edge), of index tet, with barycentric weights of its
/// vertices (cell centre, face point-average, face point edge, face point edge + 1); cell −1
/// when the point is outside the mesh, then exitPatch is the patch the search left through (or
/// −1) and exitFace the boundary face the walk reached (−1 when not known).
struct TetLocation {
    int cell = -1;
    int face = -1;
    int edge = 0;
    std::array<double, 4> weights{};
    int exitPatch = -1;
    int tet = -1;
    int exitFace = -1;
    std::array<int, 2> points{-1, -1}; ///< the mesh points of vertices 2 and 3 (when found)

    bool found() const { return cell >= 0; }
};

class FoamLocator {
public:
    explicit FoamLocator(const FoamMesh& mesh);

    /// The location of point, walking from the tetrahedron of startCell that faces it (a
    /// global search when startCell < 0).
    TetLocation locate(const Vec3& point, int startCell) const;
    /// The location of point, walking from tetrahedron startTet (a global search when
    /// startTet < 0).
    TetLocation locateFrom(const Vec3& point, int startTet) const;
    /// The location of point by the bin grid (a walk from the bin's cell with the nearest
    /// centre; else the first of its cells that holds it), or outside with the patch of the
    /// boundary face that walk reached (also for a point outside the mesh's box).
    TetLocation locateGlobally(const Vec3& point) const;
    /// The location of point within cell, if the cell holds it (weights ≥ −tolerance).
    std::optional<TetLocation> locateInCell(const Vec3& point, int cell) const;

    /// Vertices of tetrahedron (cell, face, edge) in weight order.
    std::array<Vec3, 4> vertices(int cell, int face, int edge) const;
    /// The index of tetrahedron (cell, face, edge), and back (weights left zero).
    int tetIndex(int cell, int face, int edge) const;
    TetLocation tetAt(int tet) const;
    /// One past the largest tetrahedron index.
    int tetIndexEnd() const { return 2 * static_cast<int>(mesh_.facePoints.size()); }
    const Vec3& faceMidpoint(int face) const { return faceMidpoints_[face]; }

    /// Barycentric weights below −tolerance mean outside (relative to the tetrahedron).
    static constexpr double tolerance = 1e-10;

private:
    /// The visibility walk from startTet: the location holding point, or not found with
    /// boundaryFace the boundary face it reached (−1 when it was lost: a cycle, an open cell).
    TetLocation walk(const Vec3& point, int startTet, int& boundaryFace) const;
    /// The tetrahedron of cell facing point from the cell centre, where a walk starts.
    int startTetrahedron(const Vec3& point, int cell) const;

    const FoamMesh& mesh_;
    std::vector<Vec3> faceMidpoints_; ///< point average of each face
    std::vector<int> slotFace_;       ///< the face of each face point slot (mesh.facePoints)
    /// The tetrahedron of the same cell across each tetrahedron's triangle (centre, face point
    /// edge, edge + 1), −1 for an open cell.
    std::vector<int> acrossSpoke_;
    // Bin grid: cells whose bounding box overlaps bin b are binCells[binOffsets[b] ..].
    Vec3 gridOrigin_ = Vec3::Zero();
    Vec3 binSize_ = Vec3::Ones();
    std::array<int, 3> bins_{1, 1, 1};
    std::vector<int> binOffsets_;
    std::vector<int> binCells_;
    std::vector<Vec3> cellLow_, cellHigh_; ///< each cell's bounding box, with slack
};

/// Barycentric weights of point in the tetrahedron with the given vertices: λ_i = d·n_i / det
/// with d = point − tet[0], n_i the cross product of the other two edges from tet[0] and det the
/// edges' triple product (Cramer's rule); inline, as the walk calls it once a step.
inline std::array<double, 4> barycentricWeights(const std::array<Vec3, 4>& tet, const Vec3& point) {
    const Vec3 e1 = tet[1] - tet[0], e2 = tet[2] - tet[0], e3 = tet[3] - tet[0];
    const Vec3 n1 = e2.cross(e3);
    const double det = e1.dot(n1);
    if (det == 0) return {-1, -1, -1, -1}; // a flat tetrahedron holds nothing
    const Vec3 d = (point - tet[0]) * (1 / det);
    const double l1 = d.dot(n1), l2 = d.dot(e3.cross(e1)), l3 = d.dot(e1.cross(e2));
    return {1 - l1 - l2 - l3, l1, l2, l3};
}

} // namespace slides
