#include "slides/carrier/analytic_jet.h"

#include "slides/carrier/bickley_batch.h"
#include "slides/carrier/carrier_settings.h"
#include "slides/core/name_table.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace slides {

// With e = expm1(−2|η|): tanh|η| = −e/(2 + e), sech²η = 4(1 + e)/(2 + e)², accurate for small
// and large |η| alike (one transcendental call). With g(η) = 2η sech²η − tanh η (Eq. 5.11's
// bracket), g'(η) = sech²η (1 − 4η tanh η), and ∂η/∂s = −(2/3) η/s, ∂η/∂y = C3 s^(−2/3):
//   ∂u/∂s = C1 s^(−4/3) sech²η (−1/3 + (4/3) η tanh η),   ∂u/∂y = −2 C1 C3 s^(−1) sech²η tanh η,
//   ∂v/∂s = −(2/3) C2 s^(−5/3) (g + η g'),                 ∂v/∂y = C2 C3 s^(−4/3) g',
//   v/y   = C2 C3 s^(−4/3) g/η,  g/η = 2 sech²η − tanh η/η  (→ 1 = g'(0) as η → 0).
ProfileSample BickleyProfile::at(double s, double y) const {
    const double cbrtS = std::cbrt(s);
    const double s23 = cbrtS * cbrtS;
    const double eta = C3 * y / s23;
    const double e = std::expm1(-2.0 * std::abs(eta));
    const double tanhEta = std::copysign(-e / (2.0 + e), eta);
    const double sech2 = 4.0 * (1.0 + e) / ((2.0 + e) * (2.0 + e));
    const double g = 2.0 * eta * sech2 - tanhEta;
    const double dgdEta = sech2 * (1.0 - 4.0 * eta * tanhEta);
    const double eta2 = eta * eta;
    // tanh η/η by its Taylor series below |η| = 1e-2 (next term 62η⁸/2835 < 3e-18).
    const double tanhOverEta =
        eta2 < 1e-4 ? 1.0 - eta2 * (1.0 / 3.0 - eta2 * (2.0 / 15.0 - eta2 * 17.0 / 315.0))
                    : tanhEta / eta;
    ProfileSample p;
    p.u = C1 * sech2 / cbrtS;
    p.dudS = C1 * sech2 * (-1.0 / 3.0 + 4.0 / 3.0 * eta * tanhEta) / (s * cbrtS);
    p.dudY = -2.0 * C1 * C3 * sech2 * tanhEta / s;
    p.v = C2 * g / s23;
    p.dvdS = -2.0 / 3.0 * C2 * (g + eta * dgdEta) / (s * s23);
    p.dvdY = C2 * C3 * dgdEta / (s * cbrtS);
    p.vOverY = C2 * C3 * (2.0 * sech2 - tanhOverEta) / (s * cbrtS);
    return p;
}

namespace {

void require(bool condition, const std::string& message) {
    if (!condition) throw std::invalid_argument("analyticJet: " + message);
}

std::string number(double value) {
    std::ostringstream text;
    text.precision(10);
    text << value;
    return text.str();
}

BickleyProfile bickleyCoefficients(const JetNozzle& nozzle, const AnalyticJetParameters& jet) {
    const double U0 = jet.nozzleVelocity;
    require(std::isfinite(U0) && U0 > 0, "nozzleVelocity must be positive, got " + number(U0));
    require(jet.C1.has_value() == jet.C3.has_value(), "give C1 and C3 together (or neither)");
    require(!jet.C2 || jet.C1, "C2 follows from C1 and C3 (C2 = C1/(3 C3)); give those too");
    BickleyProfile profile;
    if (jet.C1) {
        profile.C1 = *jet.C1;
        profile.C3 = *jet.C3;
        require(std::isfinite(profile.C1) && profile.C1 > 0, "C1 must be positive");
        require(std::isfinite(profile.C3) && profile.C3 > 0, "C3 must be positive");
    } else {
        const double nu = jet.viscosity;
        require(std::isfinite(nu) && nu > 0, "viscosity must be positive, got " + number(nu));
        const double K = 2.0 * nozzle.radius * U0 * U0; // slot of half-width b = radius
        profile.C1 = std::cbrt(3.0 * K * K / (32.0 * nu));
        profile.C3 = std::cbrt(K / (48.0 * nu * nu));
    }
    profile.C2 = profile.C1 / (3.0 * profile.C3); // continuity (analytic_jet.h)
    if (jet.C2)
        require(std::abs(*jet.C2 - profile.C2) <= 1e-9 * profile.C2,
                "C2 = " + number(*jet.C2) +
                    " contradicts continuity of Eq. 5.10/5.11, which "
                    "requires C2 = C1/(3 C3) = " +
                    number(profile.C2));
    return profile;
}

} // namespace

AnalyticJet::AnalyticJet(const JetNozzle& nozzle, const AnalyticJetParameters& parameters)
    : SimilarityJet(bickleyCoefficients(nozzle, parameters), nozzle, parameters.profile,
                    parameters.coreLength, parameters.nozzleVelocity) {}

void AnalyticJet::sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                         CarrierSample& out) const {
    if (needs.velocityGradient) return SimilarityJet::sample(points, time, needs, out);
    out.resize(points.size(), needs); // U alone: the SIMD kernel
    sampleBickleyVelocity(frame(), profile(), points, out.velocity);
}

std::string AnalyticJet::describe() const {
    std::ostringstream text;
    text.precision(4);
    text << "analyticJet (" << nameOf(jetGeometryNames(), frame().geometry())
         << " sech², Eq. 5.10/5.11): C1 = " << C1() << " m^(4/3)/s, C2 = " << C2()
         << " m^(5/3)/s, C3 = " << C3() << " m^(-1/3), K = " << momentumFlux()
         << " m^3/s^2, virtual origin " << virtualOrigin() << " m, core " << frame().coreLength()
         << " m";
    return text.str();
}

} // namespace slides
