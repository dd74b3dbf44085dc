// AnalyticJet: the sech² jet of Eq. 5.10/5.11 of the reference, which is Bickley's planar laminar
// jet (Schlichting, Boundary-Layer Theory, "plane jet"), used planar or axisymmetrically (y → r).
//
//     carrier { type analyticJet;
//               analyticJetCoeffs { profile axisymmetric; nozzleVelocity 25; coreLength 4e-3;
//                                   effectiveViscosity 1.4e-3; /* or C1 7.48; C3 29.8; */ } }
//
//   u = C1 s^(−1/3) sech²η,   v = C2 s^(−2/3) [2η sech²η − tanh η],   η = C3 y / s^(2/3)
//
// (the PDF text of Eq. 5.11 lost the y in its first term: 2 C3 y/x^(2/3) sech²η = 2η sech²η).
// Continuity fixes C2: the stream function ψ = (C1/C3) s^(1/3) tanh η gives
//   u = ∂ψ/∂y = C1 s^(−1/3) sech²η,
//   v = −∂ψ/∂s = (C1/(3 C3)) s^(−2/3) [2η sech²η − tanh η]   (∂η/∂s = −(2/3) η/s),
// so C2 = C1/(3 C3), and ∂u/∂s + ∂v/∂y = 0 identically.
// From the kinematic momentum flux per unit depth K = J/ρ = ∫u² dy = (4/3) C1²/C3 and the
// viscosity ν (the fluid's, or an effective one for turbulent spreading), Schlichting's solution
//   C1 = (3K²/(32ν))^(1/3), C3 = (K/(48ν²))^(1/3), C2 = (Kν/6)^(1/3)
// (his 0.4543, 0.2752, 0.5503 are the cube roots of 3/32, 1/48, 1/6). For a slot of half-width
// b = nozzle radius and exit velocity U0, K = 2 b U0². C1 and C3 may instead be given explicitly
// (C2, if also given, must equal C1/(3 C3)). The virtual origin, where the centreline speed
// C1 s^(−1/3) equals U0, is s0 = (C1/U0)³; core and coordinates as in carrier/jet_frame.h.
//
// planar:       y = d·crossSpanDirection, U = u e_a + v e_y — an exact Navier–Stokes boundary-layer
//               solution, divergence-free.
// axisymmetric: the reference's 3-D use, y → r, U = u e_a + v e_r (v < 0 far out: entrainment
//               toward the axis). This substitution does NOT satisfy 3-D continuity: ∇·U = v/r ≠ 0.
//               It is the reference's model; for a mass-conserving round jet use roundLaminarJet.
#pragma once

#include "slides/carrier/similarity_jet.h"

#include <cmath>
#include <numbers>
#include <optional>
#include <string>

namespace slides {

struct AnalyticJetParameters {
    JetGeometry profile = JetGeometry::axisymmetric;
    double nozzleVelocity = 0; ///< U0 [m/s]
    double viscosity = 0;      ///< ν [m²/s] that sets the spreading; unused when C1, C3 are given
    double coreLength = 0;     ///< unentrained core [m]
    std::optional<double> C1;  ///< [m^(4/3)/s], with C3
    std::optional<double> C2;  ///< [m^(5/3)/s], optional; must equal C1/(3 C3)
    std::optional<double> C3;  ///< [m^(−1/3)], with C1
};

/// Eq. 5.10/5.11 and their closed-form derivatives.
struct BickleyProfile {
    double C1 = 0, C2 = 0, C3 = 0;
    ProfileSample at(double s, double y) const;
    double centrelineVelocity(double s) const { return C1 / std::cbrt(s); } ///< C1 s^(−1/3)
    /// y½ where sech²η = 1/2 (η½ = arccosh √2): η½ s^(2/3)/C3 [m].
    double halfWidth(double s) const {
        return std::acosh(std::numbers::sqrt2) * std::cbrt(s * s) / C3;
    }
    double virtualOrigin(double U0) const { return std::pow(C1 / U0, 3); } ///< (C1/U0)³ [m]
    /// ∫_from^to ds/u_c(s) = (3/(4 C1)) (to^(4/3) − from^(4/3)): the time the centreline flow
    /// takes from s = from to s = to [s].
    double travelTime(double from, double to) const {
        return 0.75 * (to * std::cbrt(to) - from * std::cbrt(from)) / C1;
    }
};

class AnalyticJet final : public SimilarityJet<BickleyProfile> {
public:
    /// Throws std::invalid_argument (clear message) for U0 ≤ 0, ν ≤ 0 without explicit
    /// coefficients, only one of C1/C3, non-positive C1/C3, a C2 that contradicts continuity
    /// (|C2 − C1/(3C3)| > 1e-9·C1/(3C3)), or an invalid nozzle (see JetFrame).
    AnalyticJet(const JetNozzle& nozzle, const AnalyticJetParameters& parameters);

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override;
    std::string describe() const override;

    double C1() const { return profile().C1; } ///< [m^(4/3)/s]
    double C2() const { return profile().C2; } ///< [m^(5/3)/s]
    double C3() const { return profile().C3; } ///< [m^(−1/3)]
    /// K = (4/3) C1²/C3 = ∫u² dy per unit depth (= 2 b U0² unless C1, C3 were given) [m³/s²].
    double momentumFlux() const { return 4.0 / 3.0 * C1() * C1() / C3(); }
};

} // namespace slides
