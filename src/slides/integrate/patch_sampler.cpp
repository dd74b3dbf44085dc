#include "slides/integrate/patch_sampler.h"

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace slides {

PatchSampler::PatchSampler(std::vector<PatchTriangle> triangles,
                           std::optional<AxisymmetricFrame> sweep)
    : triangles_(std::move(triangles)), sweep_(std::move(sweep)) {
    double total = 0;
    for (const PatchTriangle& t : triangles_) {
        total += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
        cumulativeArea_.push_back(total);
    }
    if (!(total > 0)) throw std::logic_error("a patch to inject from has no area");
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
    // Off the face by a hair, so that locating the point finds the cell behind the face.
    const Vec3 inGas = onFace + 1e-9 * std::sqrt(across.norm()) * normal;
    if (!sweep_) return {inGas, normal};
    // Onto the centre plane along the hoop direction, then about the axis.
    const AxisymmetricFrame& frame = *sweep_;
    const Vec3 hoop = frame.axis.cross(frame.radial);
    const Vec3 onProfile = inGas - (inGas - frame.origin).dot(hoop) * hoop;
    const Vec3 profileNormal = (normal - normal.dot(hoop) * hoop).normalized();
    const Mat3 turn =
        Eigen::AngleAxisd(2 * std::numbers::pi * uniformTurn, frame.axis).toRotationMatrix();
    return {frame.origin + turn * (onProfile - frame.origin), turn * profileNormal, turn};
}

} // namespace slides
