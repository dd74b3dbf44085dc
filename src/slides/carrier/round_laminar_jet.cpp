#include "slides/carrier/round_laminar_jet.h"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>

namespace slides {

// With q = 1 + ξ²/4, f = q^(−2), f' = −ξ q^(−3), h = (ξ − ξ³/4) f, h' = (1 − 3ξ²/4) f + (ξ − ξ³/4)
// f', ∂ξ/∂s = −ξ/s and ∂ξ/∂r = similarity/s (A = amplitude, B = radialAmplitude, c = similarity):
//   ∂u/∂s = −A (f + ξ f')/s²,   ∂u/∂r = A c f'/s²,
//   ∂v/∂s = −B (h + ξ h')/s²,   ∂v/∂r = B c h'/s²,
//   v/r   = B c (1 − ξ²/4) f/s²   (exact, no division by r).
ProfileSample RoundLaminarProfile::at(double s, double r) const {
    const double xi = similarity * r / s;
    const double xi2 = xi * xi;
    const double q = 1.0 + 0.25 * xi2;
    const double f = 1.0 / (q * q);
    const double dfdXi = -xi * f / q;
    const double shape = 1.0 - 0.25 * xi2; // h = ξ·shape·f
    const double h = xi * shape * f;
    const double dhdXi = (1.0 - 0.75 * xi2) * f + xi * shape * dfdXi;
    const double s2 = s * s;
    ProfileSample p;
    p.u = amplitude * f / s;
    p.dudS = -amplitude * (f + xi * dfdXi) / s2;
    p.dudY = amplitude * similarity * dfdXi / s2;
    p.v = radialAmplitude * h / s;
    p.dvdS = -radialAmplitude * (h + xi * dhdXi) / s2;
    p.dvdY = radialAmplitude * similarity * dhdXi / s2;
    p.vOverY = radialAmplitude * similarity * shape * f / s2;
    return p;
}

namespace {

void require(bool condition, const std::string& message) {
    if (!condition) throw std::invalid_argument("roundLaminarJet: " + message);
}

/// K = π R² U0² of a round nozzle of radius R [m⁴/s²].
double roundMomentumFlux(const JetNozzle& nozzle, const RoundLaminarJetParameters& jet) {
    return std::numbers::pi * nozzle.radius * nozzle.radius * jet.nozzleVelocity *
           jet.nozzleVelocity;
}

RoundLaminarProfile roundProfile(double K, const RoundLaminarJetParameters& jet) {
    const double nu = jet.viscosity;
    require(std::isfinite(jet.nozzleVelocity) && jet.nozzleVelocity > 0,
            "nozzleVelocity must be positive");
    require(std::isfinite(nu) && nu > 0, "viscosity must be positive");
    RoundLaminarProfile profile;
    profile.amplitude = 3.0 * K / (8.0 * std::numbers::pi * nu);
    profile.radialAmplitude = std::sqrt(3.0 * K / std::numbers::pi) / 4.0;
    profile.similarity = profile.radialAmplitude / nu;
    return profile;
}

} // namespace

RoundLaminarJet::RoundLaminarJet(const JetNozzle& nozzle,
                                 const RoundLaminarJetParameters& parameters)
    : SimilarityJet(roundProfile(roundMomentumFlux(nozzle, parameters), parameters), nozzle,
                    JetGeometry::axisymmetric, parameters.coreLength, parameters.nozzleVelocity),
      momentumFlux_(roundMomentumFlux(nozzle, parameters)) {}

std::string RoundLaminarJet::describe() const {
    std::ostringstream text;
    text.precision(4);
    text << "roundLaminarJet (Schlichting's round laminar jet): K = " << momentumFlux_
         << " m^4/s^2, virtual origin " << virtualOrigin() << " m, core " << frame().coreLength()
         << " m";
    return text.str();
}

} // namespace slides
