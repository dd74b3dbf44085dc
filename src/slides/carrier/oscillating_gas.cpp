#include "slides/carrier/oscillating_gas.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace slides {

Vec3 OscillatingGas::velocity(double time) const {
    return std::sin(angularFrequency_ * time) * amplitude_;
}

Vec3 OscillatingGas::acceleration(double time) const {
    return angularFrequency_ * std::cos(angularFrequency_ * time) * amplitude_;
}

void OscillatingGas::sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                            CarrierSample& out) const {
    out.resize(points.size(), needs);
    std::fill(out.velocity.begin(), out.velocity.end(), velocity(time));
    std::fill(out.velocityGradient.begin(), out.velocityGradient.end(), Mat3::Zero());
    std::fill(out.velocityLaplacian.begin(), out.velocityLaplacian.end(), Vec3::Zero());
    fillLaminarScalars(out);
    std::fill(out.velocityTimeDerivative.begin(), out.velocityTimeDerivative.end(),
              acceleration(time));
}

std::string OscillatingGas::describe() const {
    std::ostringstream text;
    text << "oscillatingGas (U = " << amplitude_.norm()
         << " m/s, f = " << angularFrequency_ / (2 * std::numbers::pi) << " Hz)";
    return text.str();
}

} // namespace slides
