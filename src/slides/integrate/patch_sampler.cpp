#include "slides/integrate/patch_sampler.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace slides {

PatchSampler::PatchSampler(std::vector<PatchTriangle> triangles)
    : triangles_(std::move(triangles)) {
    double total = 0;
    for (const PatchTriangle& t : triangles_) {
        total += 0.5 * (t[1] - t[0]).cross(t[2] - t[0]).norm();
        cumulativeArea_.push_back(total);
    }
    if (!(total > 0)) throw std::logic_error("a patch to inject from has no area");
}

PatchSampler::Point PatchSampler::draw(double uniformArea, double u1, double u2) const {
    const double target = uniformArea * area();
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
    return {onFace + 1e-9 * std::sqrt(across.norm()) * normal, normal};
}

} // namespace slides
