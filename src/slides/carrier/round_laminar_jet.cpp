#include "slides/carrier/round_laminar_jet.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace slides {

ProfileSample RoundLaminarProfile::at(double s, double r) const {
    const double xi = similarity * r / s;
    const double q = 1.0 + 0.25 * xi * xi;
    const double f = 1.0 / (q * q);               // (1 + ξ²/4)^(−2)
    const double dfdXi = -xi / (q * q * q);
    const double h = (xi - 0.25 * xi * xi * xi) * f; // radial shape
    const double dhdXi = (1.0 - 0.75 * xi * xi) * f + (xi - 0.25 * xi * xi * xi) * dfdXi;
    ProfileSample p;
    p.u = amplitude * f / s;
    p.dudS = -amplitude * (f + xi * dfdXi) / (s * s);
    p.dudY = amplitude * similarity * dfdXi / (s * s);
    p.v = radialAmplitude * h / s;
    p.dvdS = -radialAmplitude * (h + xi * dhdXi) / (s * s);
    p.dvdY = radialAmplitude * similarity * dhdXi / (s * s);
    return p;
}

RoundLaminarJet::RoundLaminarJet(const NozzleSettings& nozzle, const CarrierSettings& settings) {
    const double nu = settings.viscosity;
    const double U0 = settings.nozzleVelocity;
    momentumFlux_ = std::numbers::pi * nozzle.radius * nozzle.radius * U0 * U0;
    const double K = momentumFlux_;
    profile_.amplitude = 3.0 * K / (8.0 * std::numbers::pi * nu);
    profile_.radialAmplitude = std::sqrt(3.0 * K / std::numbers::pi) / 4.0;
    profile_.similarity = profile_.radialAmplitude / nu;
    frame_.nozzle = nozzle;
    frame_.geometry = JetProfileKind::axisymmetric;
    frame_.coreLength = settings.coreLength;
    frame_.virtualOrigin = profile_.amplitude / U0;
}

void RoundLaminarJet::sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                             CarrierSample& out) const {
    frame_.sample(profile_, points, needs, out);
}

std::string RoundLaminarJet::describe() const {
    std::ostringstream text;
    text << "roundLaminarJet (Schlichting): K = " << momentumFlux_ << " m^4/s^2, virtual origin "
         << frame_.virtualOrigin << " m, core " << frame_.coreLength << " m";
    return text.str();
}

} // namespace slides
