// In-memory OpenFOAM meshes for tests and benchmarks: an n×n×n hex block of the unit cube,
// optionally distorted by a smooth map (curved, non-orthogonal cells with warped faces).
#pragma once

#include "slides/carrier/foam_mesh.h"

#include <cmath>
#include <functional>

namespace slides::testing {

/// The unit cube split into n³ hexahedra, points moved by distortion(x); one patch "walls" of
/// type wall around it (so every boundary face has a value).
inline FoamMesh hexBlockMesh(int n, const std::function<Vec3(const Vec3&)>& distortion) {
    FoamMesh mesh;
    const auto pointIndex = [n](int i, int j, int k) { return (k * (n + 1) + j) * (n + 1) + i; };
    const auto cellIndex = [n](int i, int j, int k) { return (k * n + j) * n + i; };
    for (int k = 0; k <= n; ++k)
        for (int j = 0; j <= n; ++j)
            for (int i = 0; i <= n; ++i) mesh.points.push_back(distortion(Vec3(i, j, k) / n));
    mesh.faceOffsets.push_back(0);
    // The face on the +axis side of point (i, j, k), normal along +axis (right-handed).
    const auto addFace = [&](int axis, int i, int j, int k, bool reversed) {
        int corner[4][3];
        const int a = (axis + 1) % 3, b = (axis + 2) % 3;
        const int base[3] = {i, j, k};
        const int offsets[4][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
        for (int c = 0; c < 4; ++c) {
            for (int d = 0; d < 3; ++d) corner[c][d] = base[d];
            corner[c][a] += offsets[c][0];
            corner[c][b] += offsets[c][1];
        }
        for (int c = 0; c < 4; ++c) {
            const int* p = corner[reversed ? 3 - c : c];
            mesh.facePoints.push_back(pointIndex(p[0], p[1], p[2]));
        }
        mesh.faceOffsets.push_back(static_cast<int>(mesh.facePoints.size()));
    };
    for (int k = 0; k < n; ++k) // internal faces
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i)
                for (int axis = 0; axis < 3; ++axis) {
                    int next[3] = {i, j, k};
                    if (++next[axis] >= n) continue;
                    int at[3] = {i, j, k};
                    at[axis] += 1;
                    addFace(axis, at[0], at[1], at[2], false);
                    mesh.owner.push_back(cellIndex(i, j, k));
                    mesh.neighbour.push_back(cellIndex(next[0], next[1], next[2]));
                }
    const int internal = static_cast<int>(mesh.owner.size());
    for (int axis = 0; axis < 3; ++axis)
        for (int side = 0; side < 2; ++side)
            for (int u = 0; u < n; ++u)
                for (int v = 0; v < n; ++v) {
                    int cell[3], at[3];
                    cell[axis] = side ? n - 1 : 0;
                    cell[(axis + 1) % 3] = u;
                    cell[(axis + 2) % 3] = v;
                    for (int d = 0; d < 3; ++d) at[d] = cell[d];
                    at[axis] = side ? n : 0;
                    addFace(axis, at[0], at[1], at[2], side == 0);
                    mesh.owner.push_back(cellIndex(cell[0], cell[1], cell[2]));
                }
    mesh.cellCount = n * n * n;
    mesh.patches.push_back({"walls", PatchType::wall, internal, mesh.faceCount() - internal});
    mesh.computeGeometry();
    return mesh;
}

/// A smooth distortion of the unit cube that keeps its cells valid.
inline Vec3 wavyDistortion(const Vec3& x) {
    const double pi = std::acos(-1.0);
    return x + 0.06 * Vec3(std::sin(pi * x.y()) * std::sin(2 * pi * x.z()),
                           std::sin(pi * x.z()) * std::sin(2 * pi * x.x()),
                           std::sin(pi * x.x()) * std::sin(2 * pi * x.y()));
}

} // namespace slides::testing
