#include "slides/integrate/patch_sampler.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace slides {
namespace {

/// How far a point is drawn off its face into the gas, of a triangle whose edges' cross
/// product is `across` (2 area): 1e-9 of its size, so that locating the point finds the cell
/// behind the face.
double hairOf(const Vec3& across) { return 1e-9 * std::sqrt(across.norm()); }

} // namespace

PatchSampler::PatchSampler(std::vector<PatchTriangle> triangles,
                           std::optional<AxisymmetricFrame> sweep)
    : triangles_(std::move(triangles)), sweep_(std::move(sweep)) {
    double total = 0, hair = 0;
    bounds_ = {Vec3::Constant(INFINITY), Vec3::Constant(-INFINITY)};
    for (const PatchTriangle& t : triangles_) {
        const Vec3 across = (t[1] - t[0]).cross(t[2] - t[0]);
        total += 0.5 * across.norm();
        cumulativeArea_.push_back(total);
        hair = std::max(hair, hairOf(across));
        for (const Vec3& corner : t) {
            bounds_.min = bounds_.min.cwiseMin(corner);
            bounds_.max = bounds_.max.cwiseMax(corner);
        }
    }
    if (!(total > 0)) throw std::logic_error("a patch to inject from has no area");
    // A drawn point may lie a few roundings outside (its face's, its turn's): 1e-12 of the
    // largest coordinate covers them.
    hair += 1e-12 * std::max(bounds_.min.cwiseAbs().maxCoeff(), bounds_.max.cwiseAbs().maxCoeff());
    if (!sweep_) {
        bounds_.min.array() -= hair;
        bounds_.max.array() += hair;
        return;
    }
    // Swept: a point at axial coordinate a and distance r from the axis goes round to
    // origin + a axis + r u (u ⟂ axis, unit), whose component i lies within r √(1 − axisᵢ²) of
    // the axis point's. Moving it onto the centre plane keeps a and does not increase r.
    const AxisymmetricFrame& frame = *sweep_;
    double lowest = INFINITY, highest = -INFINITY, farthest = 0;
    for (const PatchTriangle& t : triangles_)
        for (const Vec3& corner : t) {
            const Vec3 offset = corner - frame.origin;
            const double along = offset.dot(frame.axis);
            lowest = std::min(lowest, along);
            highest = std::max(highest, along);
            farthest = std::max(farthest, (offset - along * frame.axis).norm());
        }
    const Vec3 low = frame.origin + (lowest - hair) * frame.axis,
               high = frame.origin + (highest + hair) * frame.axis;
    const Vec3 rim =
        (farthest + hair) * (1 - frame.axis.array().square()).cwiseMax(0.0).sqrt().matrix();
    bounds_ = {low.cwiseMin(high) - rim, low.cwiseMax(high) + rim};
}

double PatchSampler::area() const {
    const double faces = cumulativeArea_.back();
    return sweep_ ? faces * std::numbers::pi / std::tan(0.5 * sweep_->wedgeAngle) : faces;
}

PatchSampler::Point PatchSampler::draw(double uniformArea, double u1, double u2,
                                       double uniformTurn) const {
    const double target = uniformArea * cumulativeArea_.back();
    const auto k = std::min<std::size_t>(
        static_cast<std::size_t>(
            std::upper_bound(cumulativeArea_.begin(), cumulativeArea_.end(), target) -
            cumulativeArea_.begin()),
        triangles_.size() - 1);
    const PatchTriangle& t = triangles_[k];
    const double root = std::sqrt(u1);
    const Vec3 onFace = (1 - root) * t[0] + root * (1 - u2) * t[1] + root * u2 * t[2];
    const Vec3 across = (t[1] - t[0]).cross(t[2] - t[0]); // into the gas, |.| = 2 area
    const Vec3 normal = across.normalized();
    const Vec3 inGas = onFace + hairOf(across) * normal;
    if (!sweep_) return {inGas, normal, Mat3::Identity(), k};
    // Onto the centre plane along the hoop direction, then about the axis.
    const AxisymmetricFrame& frame = *sweep_;
    const Vec3 hoop = frame.axis.cross(frame.radial);
    const Vec3 onProfile = inGas - (inGas - frame.origin).dot(hoop) * hoop;
    const Vec3 profileNormal = (normal - normal.dot(hoop) * hoop).normalized();
    const Mat3 turn =
        Eigen::AngleAxisd(2 * std::numbers::pi * uniformTurn, frame.axis).toRotationMatrix();
    return {frame.origin + turn * (onProfile - frame.origin), turn * profileNormal, turn, k};
}

} // namespace slides
