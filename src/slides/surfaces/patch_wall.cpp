#include "slides/surfaces/patch_wall.h"

#include "slides/core/error.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace slides {

PatchWall::PatchWall(const std::vector<PatchTriangle>& triangles) {
    if (triangles.empty()) throw std::logic_error("a patch surface without faces");
    Vec3 weightedNormal = Vec3::Zero(), weightedCentroid = Vec3::Zero();
    double area = 0;
    std::vector<Vec3> middles;
    std::vector<double> reaches;
    for (const PatchTriangle& triangle : triangles) {
        const Vec3 b = triangle[1] - triangle[0], c = triangle[2] - triangle[0];
        const Vec3 areaVector = 0.5 * b.cross(c);
        if (!(areaVector.norm() > 0)) continue; // a degenerate fan triangle meets nothing
        const Vec3 middle = (triangle[0] + triangle[1] + triangle[2]) / 3;
        vertex_.push_back(triangle[0]);
        edgeB_.push_back(b);
        edgeC_.push_back(c);
        normal_.push_back(areaVector.normalized());
        middles.push_back(middle);
        double reach = 0;
        for (const Vec3& point : triangle) reach = std::max(reach, (point - middle).norm());
        reaches.push_back(reach);
        weightedNormal += areaVector;
        weightedCentroid += areaVector.norm() * middle;
        area += areaVector.norm();
    }
    if (normal_.empty()) throw std::logic_error("a patch surface of zero area");
    centroid_ = weightedCentroid / area;
    meanNormal_ = weightedNormal.norm() > 1e-6 * area ? weightedNormal.normalized() : Vec3::Zero();

    // Class c holds the reaches in (r_min 2^(c−1), r_min 2^c]; each class's grid has cells of
    // twice its reach, so a sphere's query spans a few cells.
    const double smallest = *std::min_element(reaches.begin(), reaches.end());
    for (std::uint32_t k = 0; k < reaches.size(); ++k) {
        const auto c =
            static_cast<std::size_t>(std::max(0.0, std::ceil(std::log2(reaches[k] / smallest))));
        if (classes_.size() <= c) classes_.resize(c + 1);
        SizeClass& size = classes_[c];
        if (size.triangles.empty()) size.lower = size.upper = vertex_[k];
        size.triangles.push_back(k);
        size.reach = std::max(size.reach, reaches[k]);
        for (const Vec3& point :
             std::array<Vec3, 3>{vertex_[k], vertex_[k] + edgeB_[k], vertex_[k] + edgeC_[k]}) {
            size.lower = size.lower.cwiseMin(point);
            size.upper = size.upper.cwiseMax(point);
        }
    }
    std::erase_if(classes_, [](const SizeClass& size) { return size.triangles.empty(); });
    for (SizeClass& size : classes_) {
        std::vector<Vec3> points;
        for (const std::uint32_t k : size.triangles) points.push_back(middles[k]);
        size.grid.build(points, 2 * size.reach);
    }
}

std::optional<double> PatchWall::touchFraction(std::size_t k, const Vec3& start, const Vec3& end,
                                               double radius) const {
    const Vec3& n = normal_[k];
    const double startHeight = (start - vertex_[k]).dot(n);
    const double startGap = startHeight - radius, endGap = (end - vertex_[k]).dot(n) - radius;
    if (endGap > 0 || startHeight < 0) return std::nullopt;
    const double fraction = startGap <= 0 ? 0.0 : startGap / (startGap - endGap);
    // Over the triangle: the barycentric weights of the centre's projection, all ≥ 0.
    const Vec3 offset = start + fraction * (end - start) - vertex_[k];
    const Vec3 &b = edgeB_[k], &c = edgeC_[k];
    const double bb = b.dot(b), bc = b.dot(c), cc = c.dot(c);
    const double ob = offset.dot(b), oc = offset.dot(c);
    const double determinant = bb * cc - bc * bc;
    const double wb = (cc * ob - bc * oc) / determinant, wc = (bb * oc - bc * ob) / determinant;
    constexpr double edgeTolerance = 1e-9; // a touch on an edge shared by two faces is kept
    if (wb < -edgeTolerance || wc < -edgeTolerance || wb + wc > 1 + edgeTolerance)
        return std::nullopt;
    return fraction;
}

std::vector<Surface> placePatchSurfaces(std::vector<Surface> surfaces, const CarrierField& carrier,
                                        const std::filesystem::path& dictionaryFile) {
    for (Surface& surface : surfaces) {
        if (surface.patch.empty()) continue;
        const PatchWall wall(carrier.patchTriangles(surface.patch));
        const bool deposits = surface.interaction == SurfaceInteraction::deposit;
        if (deposits && !(wall.meanNormal().norm() > 0))
            throw InputError(dictionaryFile.string(), 0, "surfaces." + surface.name + ".patch",
                             "patch '" + surface.patch +
                                 "' has no mean direction (its face normals cancel): the "
                                 "deposit's height and map need one; split the patch");
        surface.point = wall.centroid();
        if (wall.meanNormal().norm() > 0) surface.normal = wall.meanNormal();
    }
    return surfaces;
}

} // namespace slides
