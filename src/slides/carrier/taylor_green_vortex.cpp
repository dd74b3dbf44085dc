#include "slides/carrier/taylor_green_vortex.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace slides {

TaylorGreenVortex::TaylorGreenVortex(double velocity, double wavelength, double viscosity,
                                     double temperature)
    : UnsteadyAnalyticCarrier(temperature), velocity_(velocity),
      wavenumber_(2 * std::numbers::pi / wavelength), viscosity_(viscosity) {}

Vec3 TaylorGreenVortex::velocity(const Vec3& x, double time) const {
    const double k = wavenumber_;
    const double amplitude = velocity_ * std::exp(-2 * viscosity_ * k * k * time);
    return {amplitude * std::sin(k * x.x()) * std::cos(k * x.y()),
            -amplitude * std::cos(k * x.x()) * std::sin(k * x.y()), 0.0};
}

Vec3 TaylorGreenVortex::kinematicPressureGradient(const Vec3& x, double time) const {
    // ∇ of (U²/4)(cos 2kx + cos 2ky) F².
    const double k = wavenumber_;
    const double scale =
        -0.5 * k * velocity_ * velocity_ * std::exp(-4 * viscosity_ * k * k * time);
    return {scale * std::sin(2 * k * x.x()), scale * std::sin(2 * k * x.y()), 0.0};
}

void TaylorGreenVortex::sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                               CarrierSample& out) const {
    out.resize(points.size(), needs);
    const double k = wavenumber_;
    const double decayRate = 2 * viscosity_ * k * k;
    const double amplitude = velocity_ * std::exp(-decayRate * time);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const double sx = std::sin(k * points[i].x()), cx = std::cos(k * points[i].x());
        const double sy = std::sin(k * points[i].y()), cy = std::cos(k * points[i].y());
        const Vec3 u(amplitude * sx * cy, -amplitude * cx * sy, 0.0);
        out.velocity[i] = u;
        if (needs.velocityGradient) {
            const double a = amplitude * k;
            Mat3& g = out.velocityGradient[i]; // g(i, j) = dU_i/dx_j
            g << a * cx * cy, -a * sx * sy, 0, a * sx * sy, -a * cx * cy, 0, 0, 0, 0;
        }
        if (needs.timeDerivative) out.velocityTimeDerivative[i] = -decayRate * u;
        if (needs.velocityLaplacian) out.velocityLaplacian[i] = -2 * k * k * u;
    }
    fillLaminarScalars(out);
}

std::string TaylorGreenVortex::describe() const {
    std::ostringstream text;
    text << "taylorGreenVortex (U = " << velocity_
         << " m/s, L = " << 2 * std::numbers::pi / wavenumber_ << " m)";
    return text.str();
}

} // namespace slides
