#include "slides/carrier/foam_locator.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

namespace slides {

FoamLocator::FoamLocator(const FoamMesh& mesh) : mesh_(mesh) {
    faceMidpoints_.resize(mesh.faceCount());
    for (int f = 0; f < mesh.faceCount(); ++f) {
        Vec3 sum = Vec3::Zero();
        for (const int p : mesh.pointsOf(f)) sum += mesh.points[p];
        faceMidpoints_[f] = sum / static_cast<double>(mesh.pointsOf(f).size());
    }
    slotFace_.resize(mesh.facePoints.size());
    for (int f = 0; f < mesh.faceCount(); ++f)
        std::fill(slotFace_.begin() + mesh.faceOffsets[f],
                  slotFace_.begin() + mesh.faceOffsets[f + 1], f);
    // Within each cell, the two tetrahedra on either side of the triangle (centre, a, b) of each
    // face edge (a, b): the edge's two faces in that cell.
    acrossSpoke_.assign(static_cast<std::size_t>(tetIndexEnd()), -1);
    std::vector<std::pair<std::pair<int, int>, int>> edges; // (low point, high point), tet
    for (int c = 0; c < mesh.cellCount; ++c) {
        edges.clear();
        for (const int f : mesh.facesOf(c)) {
            const auto ring = mesh.pointsOf(f);
            const int n = static_cast<int>(ring.size());
            for (int edge = 0; edge < n; ++edge) {
                const int a = ring[edge], b = ring[(edge + 1) % n];
                edges.push_back({{std::min(a, b), std::max(a, b)}, tetIndex(c, f, edge)});
            }
        }
        std::sort(edges.begin(), edges.end());
        for (std::size_t k = 0; k + 1 < edges.size(); ++k)
            if (edges[k].first == edges[k + 1].first) {
                acrossSpoke_[edges[k].second] = edges[k + 1].second;
                acrossSpoke_[edges[k + 1].second] = edges[k].second;
            }
    }
    // About one cell per bin.
    const Vec3 extent = (mesh.boundsMax - mesh.boundsMin).cwiseMax(1e-300);
    const double binVolume = extent.prod() / std::max(1, mesh.cellCount);
    const double side = std::cbrt(binVolume);
    for (int axis = 0; axis < 3; ++axis)
        bins_[axis] = std::clamp(static_cast<int>(extent[axis] / side), 1, 512);
    gridOrigin_ = mesh.boundsMin;
    for (int axis = 0; axis < 3; ++axis) binSize_[axis] = extent[axis] / bins_[axis];
    const auto binOf = [&](const Vec3& x, int axis) {
        return std::clamp(static_cast<int>((x[axis] - gridOrigin_[axis]) / binSize_[axis]), 0,
                          bins_[axis] - 1);
    };
    std::vector<std::array<int, 6>> ranges(mesh.cellCount);
    cellLow_.resize(mesh.cellCount);
    cellHigh_.resize(mesh.cellCount);
    std::vector<int> count(static_cast<std::size_t>(bins_[0]) * bins_[1] * bins_[2] + 1, 0);
    for (int pass = 0; pass < 2; ++pass) {
        for (int c = 0; c < mesh.cellCount; ++c) {
            auto& range = ranges[c];
            if (pass == 0) {
                Vec3 low = mesh.cellCentres[c], high = low;
                for (const int f : mesh.facesOf(c))
                    for (const int p : mesh.pointsOf(f)) {
                        low = low.cwiseMin(mesh.points[p]);
                        high = high.cwiseMax(mesh.points[p]);
                    }
                for (int axis = 0; axis < 3; ++axis) {
                    range[axis] = binOf(low, axis);
                    range[3 + axis] = binOf(high, axis);
                }
                const Vec3 slack = 1e-8 * (high - low); // weights ≥ −tolerance reach outside
                cellLow_[c] = low - slack;
                cellHigh_[c] = high + slack;
            }
            for (int i = range[0]; i <= range[3]; ++i)
                for (int j = range[1]; j <= range[4]; ++j)
                    for (int k = range[2]; k <= range[5]; ++k) {
                        const int bin = (i * bins_[1] + j) * bins_[2] + k;
                        if (pass == 0)
                            ++count[bin + 1];
                        else
                            binCells_[binOffsets_[bin] + count[bin]++] = c;
                    }
        }
        if (pass == 0) {
            binOffsets_.assign(count.size(), 0);
            for (std::size_t b = 1; b < count.size(); ++b)
                binOffsets_[b] = binOffsets_[b - 1] + count[b];
            binCells_.assign(binOffsets_.back(), 0);
            std::fill(count.begin(), count.end(), 0);
        }
    }
}

std::array<Vec3, 4> FoamLocator::vertices(int cell, int face, int edge) const {
    const auto ring = mesh_.pointsOf(face);
    const int n = static_cast<int>(ring.size());
    return {mesh_.cellCentres[cell], faceMidpoints_[face], mesh_.points[ring[edge]],
            mesh_.points[ring[(edge + 1) % n]]};
}

int FoamLocator::tetIndex(int cell, int face, int edge) const {
    return 2 * (mesh_.faceOffsets[face] + edge) + (mesh_.owner[face] == cell ? 0 : 1);
}

TetLocation FoamLocator::tetAt(int tet) const {
    const int slot = tet / 2;
    const int face = slotFace_[slot];
    const int cell = tet % 2 == 0 ? mesh_.owner[face] : mesh_.neighbour[face];
    return TetLocation{cell, face, slot - mesh_.faceOffsets[face], {}, -1, tet};
}

std::optional<TetLocation> FoamLocator::locateInCell(const Vec3& point, int cell) const {
    for (const int face : mesh_.facesOf(cell)) {
        const int n = static_cast<int>(mesh_.pointsOf(face).size());
        for (int edge = 0; edge < n; ++edge) {
            const auto weights = barycentricWeights(vertices(cell, face, edge), point);
            if (*std::min_element(weights.begin(), weights.end()) >= -tolerance) {
                const auto ring = mesh_.pointsOf(face);
                return TetLocation{cell, face,
                                   edge, weights,
                                   -1,   tetIndex(cell, face, edge),
                                   -1,   {ring[edge], ring[(edge + 1) % n]}};
            }
        }
    }
    return std::nullopt;
}

TetLocation FoamLocator::locateGlobally(const Vec3& point) const {
    TetLocation outside;
    const Vec3 slack = 1e-9 * (mesh_.boundsMax - mesh_.boundsMin); // points on the boundary
    bool inBox = true;
    for (int axis = 0; axis < 3; ++axis)
        inBox = inBox && point[axis] >= mesh_.boundsMin[axis] - slack[axis] &&
                point[axis] <= mesh_.boundsMax[axis] + slack[axis];
    std::array<int, 3> index{};
    for (int axis = 0; axis < 3; ++axis)
        index[axis] =
            std::clamp(static_cast<int>((point[axis] - gridOrigin_[axis]) / binSize_[axis]), 0,
                       bins_[axis] - 1);
    const int bin = (index[0] * bins_[1] + index[1]) * bins_[2] + index[2];
    // Walk from the bin's cell whose centre is nearest: the point is a cell or two away. Under
    // a graded mesh a bin holds up to ~100 cells, and a distance is far cheaper than a cell's
    // tetrahedra. A point outside the mesh's box walks from the nearest bin to the boundary face
    // it lies beyond: the patch it left through.
    int nearest = -1;
    double nearestDistance = INFINITY;
    for (int k = binOffsets_[bin]; k < binOffsets_[bin + 1]; ++k) {
        const double distance = (mesh_.cellCentres[binCells_[k]] - point).squaredNorm();
        if (distance < nearestDistance) {
            nearestDistance = distance;
            nearest = binCells_[k];
        }
    }
    if (nearest < 0) return outside;
    int boundaryFace = -1;
    if (const TetLocation walked = walk(point, startTetrahedron(point, nearest), boundaryFace);
        walked.found())
        return walked;
    // The walk left through the boundary (the point is outside, or beyond a concave part of
    // it) or was lost: test the bin's cells whose boxes hold the point.
    for (int k = binOffsets_[bin]; inBox && k < binOffsets_[bin + 1]; ++k) {
        const int cell = binCells_[k];
        if ((point.array() < cellLow_[cell].array()).any() ||
            (point.array() > cellHigh_[cell].array()).any())
            continue;
        if (auto found = locateInCell(point, cell)) return *found;
    }
    if (boundaryFace >= 0) {
        outside.exitPatch = mesh_.facePatch[boundaryFace];
        outside.exitFace = boundaryFace;
    }
    return outside;
}

TetLocation FoamLocator::locate(const Vec3& point, int startCell) const {
    if (startCell < 0 || startCell >= mesh_.cellCount) return locateGlobally(point);
    return locateFrom(point, startTetrahedron(point, startCell));
}

TetLocation FoamLocator::locateFrom(const Vec3& point, int startTet) const {
    if (startTet < 0 || startTet >= tetIndexEnd()) return locateGlobally(point);
    int boundaryFace = -1;
    if (const TetLocation walked = walk(point, startTet, boundaryFace); walked.found())
        return walked;
    TetLocation searched = locateGlobally(point);
    if (!searched.found() && boundaryFace >= 0) { // the walk from the particle's last place
        searched.exitPatch = mesh_.facePatch[boundaryFace];
        searched.exitFace = boundaryFace;
    }
    return searched;
}

int FoamLocator::startTetrahedron(const Vec3& point, int cell) const {
    // The face whose point-average lies most in the point's direction from the cell centre,
    // then the face point most in its direction from that average: usually the tetrahedron
    // holding the point or its neighbour, so the walk takes a step or none.
    const Vec3& centre = mesh_.cellCentres[cell];
    const Vec3 towards = point - centre;
    int face = mesh_.facesOf(cell)[0], edge = 0;
    double best = -INFINITY;
    for (const int f : mesh_.facesOf(cell)) {
        const Vec3 spoke = faceMidpoints_[f] - centre;
        const double reach = towards.dot(spoke) / spoke.squaredNorm();
        if (reach > best) {
            best = reach;
            face = f;
        }
    }
    const auto ring = mesh_.pointsOf(face);
    const Vec3 across = point - faceMidpoints_[face];
    best = -INFINITY;
    for (int j = 0; j < static_cast<int>(ring.size()); ++j) {
        const double reach = across.dot(mesh_.points[ring[j]] - faceMidpoints_[face]);
        if (reach > best) {
            best = reach;
            edge = j;
        }
    }
    return tetIndex(cell, face, edge);
}

TetLocation FoamLocator::walk(const Vec3& point, int startTet, int& boundaryFace) const {
    // The tetrahedron (cell, face, face point slots j and next) of index tet = 2 j + side.
    int tet = startTet;
    int face = slotFace_[tet / 2];
    int cell = tet % 2 == 0 ? mesh_.owner[face] : mesh_.neighbour[face];
    // A walk longer than this is cycling on a badly shaped mesh: lost.
    const int maximumSteps = 1000;
    for (int step = 0; step < maximumSteps; ++step) {
        const int slot = tet / 2, first = mesh_.faceOffsets[face],
                  end = mesh_.faceOffsets[face + 1];
        const int next = slot + 1 < end ? slot + 1 : first;
        const int a = mesh_.facePoints[slot], b = mesh_.facePoints[next];
        const auto weights = barycentricWeights(
            {mesh_.cellCentres[cell], faceMidpoints_[face], mesh_.points[a], mesh_.points[b]},
            point);
        const int k =
            static_cast<int>(std::min_element(weights.begin(), weights.end()) - weights.begin());
        if (weights[k] >= -tolerance)
            return TetLocation{cell, face, slot - first, weights, -1, tet, -1, {a, b}};
        switch (k) {
        case 0: { // across the mesh face into the next cell: the same triangle, the other side
            const int across = mesh_.across(face, cell);
            if (across < 0) {
                boundaryFace = face;
                return {};
            }
            cell = across;
            tet ^= 1;
            break;
        }
        case 1: // across the triangle (centre, p_edge, p_edge+1) to the cell's other face
            tet = acrossSpoke_[tet];
            if (tet < 0) return {}; // an open cell: lost
            face = slotFace_[tet / 2];
            break;
        case 2: tet = 2 * next + tet % 2; break; // across (centre, midpoint, p_edge+1)
        default:                                 // across (centre, midpoint, p_edge)
            tet = 2 * (slot > first ? slot - 1 : end - 1) + tet % 2;
            break;
        }
    }
    return {};
}

} // namespace slides
