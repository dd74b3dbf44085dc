#include "slides/carrier/plane_poiseuille.h"

#include <sstream>

namespace slides {

void PlanePoiseuille::sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                             CarrierSample& out) const {
    out.resize(points.size(), needs);
    const double curvature = centrelineVelocity_ / (halfWidth_ * halfWidth_); // U/h²
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double y = points[i].y();
        out.velocity[i] = {centrelineVelocity_ - curvature * y * y, 0.0, 0.0};
        if (needs.velocityGradient) { // g(i, j) = dU_i/dx_j
            out.velocityGradient[i].setZero();
            out.velocityGradient[i](0, 1) = -2 * curvature * y;
        }
        if (needs.velocityLaplacian) out.velocityLaplacian[i] = {-2 * curvature, 0.0, 0.0};
    }
    fillLaminarScalars(out);
}

std::string PlanePoiseuille::describe() const {
    std::ostringstream text;
    text << "planePoiseuille (U = " << centrelineVelocity_ << " m/s, h = " << halfWidth_ << " m)";
    return text.str();
}

} // namespace slides
