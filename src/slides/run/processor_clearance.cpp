#include "slides/run/processor_clearance.h"

#include <boost/geometry.hpp>
#include <boost/geometry/index/rtree.hpp>

#include <algorithm>
#include <cmath>

namespace slides {

namespace {

namespace bg = boost::geometry;
using Point = bg::model::point<double, 3, bg::cs::cartesian>;

Point pointOf(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

} // namespace

ProcessorClearance::ProcessorClearance(const FoamMesh& mesh, const FoamLocator& locator,
                                       int firstProcessorPatch)
    : mesh_(mesh), locator_(locator), squaredReach_(mesh.cellCount, 0.0) {
    // The processor faces' point-averages, and the farthest any face point lies from its own.
    std::vector<Point> midpoints;
    double faceReach = 0;
    for (int p = firstProcessorPatch; p < static_cast<int>(mesh.patches.size()); ++p) {
        const FoamPatch& patch = mesh.patches[p];
        for (int face = patch.start; face < patch.start + patch.size; ++face) {
            const Vec3& middle = locator.faceMidpoint(face);
            midpoints.push_back(pointOf(middle));
            for (const int point : mesh.pointsOf(face))
                faceReach = std::max(faceReach, (mesh.points[point] - middle).norm());
        }
    }
    // Each cell's own reach: the farthest of its face points from its centre.
    std::vector<double> cellReach(mesh.cellCount, 0.0);
    for (int face = 0; face < mesh.faceCount(); ++face)
        for (const int point : mesh.pointsOf(face)) {
            const auto widen = [&](int cell) {
                const double d = (mesh.points[point] - mesh.cellCentres[cell]).norm();
                cellReach[cell] = std::max(cellReach[cell], d);
            };
            widen(mesh.owner[face]);
            if (face < mesh.internalFaceCount()) widen(mesh.neighbour[face]);
        }
    if (midpoints.empty()) {
        squaredReach_.assign(mesh.cellCount, INFINITY);
        return;
    }
    const bg::index::rtree<Point, bg::index::rstar<16>> tree(midpoints);
    for (int cell = 0; cell < mesh.cellCount; ++cell) {
        const Point centre = pointOf(mesh.cellCentres[cell]);
        Point nearest;
        tree.query(bg::index::nearest(centre, 1), &nearest);
        const double reach = bg::distance(centre, nearest) - faceReach;
        if (reach > cellReach[cell]) squaredReach_[cell] = reach * reach;
    }
}

} // namespace slides
