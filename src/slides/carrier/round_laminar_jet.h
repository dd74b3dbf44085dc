// RoundLaminarJet: Schlichting's exact similarity solution of the round (axisymmetric) laminar jet
// (Schlichting 1933, ZAMM 13; Boundary-Layer Theory, "circular jet"), a mass-conserving
// alternative to the axisymmetric use of Eq. 5.10/5.11.
//
//     carrier { type roundLaminarJet;
//               roundLaminarJetCoeffs { nozzleVelocity 25; coreLength 0; effectiveViscosity 2e-4; }
//               }
//
//   u = 3K/(8πν s) · (1 + ξ²/4)^(−2),
//   v = √(3K/π)/(4 s) · (ξ − ξ³/4)(1 + ξ²/4)^(−2),      ξ = √(3K/π)/(4ν) · r/s,
//
// with K = J/ρ = ∫u² 2πr dr the kinematic momentum flux, π R² U0² for a round nozzle of radius R,
// and ν the fluid's (or an effective) viscosity. It satisfies 3-D continuity
// ∂u/∂s + (1/r)∂(r v)/∂r = 0 exactly, conserves K at every s, and carries the volume flux
// ∫u 2πr dr = 8πν s, independent of K. U = u e_a + v e_r (v < 0 for ξ > 2: entrainment).
// The virtual origin, where the centreline speed 3K/(8πν s) equals U0, is s0 = 3K/(8πν U0)
// = (3/8) R² U0/ν; core and coordinates as in carrier/jet_frame.h (geometry axisymmetric).
#pragma once

#include "slides/carrier/similarity_jet.h"

#include <cmath>
#include <numbers>
#include <string>

namespace slides {

struct RoundLaminarJetParameters {
    double nozzleVelocity = 0; ///< U0 [m/s]
    double viscosity = 0;      ///< ν [m²/s] that sets the spreading
    double coreLength = 0;     ///< unentrained core [m]
};

/// Schlichting's round jet and its closed-form derivatives.
struct RoundLaminarProfile {
    double amplitude = 0; ///< 3K/(8πν) [m²/s]: u = amplitude·(1 + ξ²/4)^(−2)/s
    double radialAmplitude = 0; ///< √(3K/π)/4 [m²/s]: v = radialAmplitude·(ξ − ξ³/4)(…)^(−2)/s
    double similarity = 0; ///< √(3K/π)/(4ν) [1]: ξ = similarity·r/s
    ProfileSample at(double s, double r) const;
    double centrelineVelocity(double s) const { return amplitude / s; } ///< 3K/(8πν s) [m/s]
    /// r½ where (1 + ξ²/4)² = 2 (ξ½ = 2 √(√2 − 1)): ξ½ s/similarity [m].
    double halfWidth(double s) const {
        return 2.0 * std::sqrt(std::numbers::sqrt2 - 1.0) * s / similarity;
    }
    double virtualOrigin(double U0) const { return amplitude / U0; } ///< 3K/(8πν U0) [m]
    /// ∫_from^to ds/u_c(s) = (to² − from²)/(2·amplitude): the time the centreline flow takes
    /// from s = from to s = to [s].
    double travelTime(double from, double to) const {
        return 0.5 * (to - from) * (to + from) / amplitude;
    }
};

class RoundLaminarJet final : public SimilarityJet<RoundLaminarProfile> {
public:
    /// Throws std::invalid_argument for U0 ≤ 0, ν ≤ 0 or an invalid nozzle (see JetFrame).
    RoundLaminarJet(const JetNozzle& nozzle, const RoundLaminarJetParameters& parameters);

    std::string describe() const override;

    double momentumFlux() const { return momentumFlux_; } ///< K = π R² U0² [m⁴/s²]

private:
    double momentumFlux_;
};

} // namespace slides
