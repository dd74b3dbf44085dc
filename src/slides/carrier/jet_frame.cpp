#include "slides/carrier/jet_frame.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace slides {

namespace {

constexpr double unitTolerance = 1e-9;

void require(bool condition, const std::string& message) {
    if (!condition) throw std::invalid_argument("jet nozzle: " + message);
}

} // namespace

JetFrame::JetFrame(const JetNozzle& nozzle, JetGeometry geometry, double coreLength,
                   double virtualOrigin)
    : nozzle_(nozzle), geometry_(geometry), coreLength_(coreLength), virtualOrigin_(virtualOrigin) {
    require(nozzle.centre.allFinite(), "centre must be finite");
    require(std::isfinite(nozzle.radius) && nozzle.radius > 0,
            "radius must be positive, got " + std::to_string(nozzle.radius));
    require(nozzle.axis.allFinite() && std::abs(nozzle.axis.norm() - 1) < unitTolerance,
            "axis must be a unit vector");
    if (geometry == JetGeometry::planar) {
        const Vec3& crossSpan = nozzle.crossSpanDirection;
        require(crossSpan.allFinite() && std::abs(crossSpan.norm() - 1) < unitTolerance &&
                    std::abs(crossSpan.dot(nozzle.axis)) < unitTolerance,
                "crossSpanDirection must be a unit vector perpendicular to axis");
    }
    require(std::isfinite(coreLength) && coreLength >= 0,
            "coreLength must be >= 0, got " + std::to_string(coreLength));
    require(std::isfinite(virtualOrigin) && virtualOrigin > 0,
            "virtual origin must be positive and finite, got " + std::to_string(virtualOrigin));
    transverse_ = Mat3::Identity() - nozzle.axis * nozzle.axis.transpose();
    axisRadial_ = nozzle.axis.unitOrthogonal();
}

} // namespace slides
