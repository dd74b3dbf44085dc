#include "slides/carrier/analytic_jet.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace slides {

ProfileSample BickleyProfile::at(double s, double y) const {
    const double eta = C3 * y / std::cbrt(s * s);
    const double tanhEta = std::tanh(eta);
    const double sech2 = 1.0 - tanhEta * tanhEta;
    const double cbrtS = std::cbrt(s);
    const double g = 2.0 * eta * sech2 - tanhEta;        // bracket of Eq. 5.11
    const double dgdEta = sech2 * (1.0 - 4.0 * eta * tanhEta);
    ProfileSample p;
    p.u = C1 * sech2 / cbrtS;
    p.dudS = C1 * sech2 * (-1.0 / 3.0 + 4.0 / 3.0 * eta * tanhEta) / (s * cbrtS);
    p.dudY = -2.0 * C1 * C3 * sech2 * tanhEta / s;
    p.v = C2 * g / (cbrtS * cbrtS);
    p.dvdS = -2.0 / 3.0 * C2 * (g + eta * dgdEta) / (s * cbrtS * cbrtS);
    p.dvdY = C2 * C3 * dgdEta / (s * cbrtS);
    return p;
}

AnalyticJet::AnalyticJet(const NozzleSettings& nozzle, const CarrierSettings& settings) {
    const double nu = settings.viscosity;
    const double K = 2.0 * nozzle.radius * settings.nozzleVelocity * settings.nozzleVelocity;
    profile_.C1 = settings.C1.value_or(std::cbrt(3.0 * K * K / (32.0 * nu)));
    profile_.C3 = settings.C3.value_or(std::cbrt(K / (48.0 * nu * nu)));
    profile_.C2 = profile_.C1 / (3.0 * profile_.C3);
    if (settings.C2 && std::abs(*settings.C2 - profile_.C2) > 1e-9 * profile_.C2)
        throw std::invalid_argument("C2 must equal C1/(3 C3) for continuity");
    frame_.nozzle = nozzle;
    frame_.geometry = settings.profile;
    frame_.coreLength = settings.coreLength;
    frame_.virtualOrigin = std::pow(profile_.C1 / settings.nozzleVelocity, 3.0);
}

void AnalyticJet::sample(std::span<const Vec3> points, double, CarrierNeeds needs,
                         CarrierSample& out) const {
    frame_.sample(profile_, points, needs, out);
}

double AnalyticJet::centrelineVelocity(double axialDistance) const {
    const double s = std::max(axialDistance - frame_.coreLength, 0.0) + frame_.virtualOrigin;
    return profile_.C1 / std::cbrt(s);
}

std::string AnalyticJet::describe() const {
    std::ostringstream text;
    text << "analyticJet (" << (frame_.geometry == JetProfileKind::planar ? "planar" : "axisymmetric")
         << " sech², Eq. 5.10/5.11): C1 = " << profile_.C1 << ", C2 = " << profile_.C2
         << ", C3 = " << profile_.C3 << ", virtual origin " << frame_.virtualOrigin
         << " m, core " << frame_.coreLength << " m";
    return text.str();
}

} // namespace slides
