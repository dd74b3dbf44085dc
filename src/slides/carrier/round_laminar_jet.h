// RoundLaminarJet: Schlichting's exact similarity solution of the round laminar jet
// (Schlichting 1933; Boundary-Layer Theory, "circular jet").
//
//   u = 3K/(8πν s) (1 + ξ²/4)^(−2),   v = √(3K/π)/(4 s) (ξ − ξ³/4)(1 + ξ²/4)^(−2),
//   ξ = √(3K/π)/(4ν) · r/s,   K = J/ρ = π R² U0²
//
// It conserves mass (∂u/∂s + (1/r)∂(r v)/∂r = 0) and momentum flux (∫u² 2πr dr = K) exactly.
// The virtual origin, where the centreline speed 3K/(8πν s) equals U0, is s0 = 3K/(8πν U0).
//
//     carrier { type roundLaminarJet; roundLaminarJetCoeffs { nozzleVelocity 25; } }
#pragma once

#include "slides/carrier/jet_frame.h"

namespace slides {

struct RoundLaminarProfile {
    double amplitude = 0;  ///< 3K/(8πν) [m²/s]
    double similarity = 0; ///< √(3K/π)/(4ν) [1/1]: ξ = similarity·r/s
    double radialAmplitude = 0; ///< √(3K/π)/4 [m²/s]
    ProfileSample at(double s, double r) const;
};

class RoundLaminarJet : public CarrierField {
public:
    RoundLaminarJet(const NozzleSettings& nozzle, const CarrierSettings& settings);

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override;
    std::string describe() const override;

    const RoundLaminarProfile& profile() const { return profile_; }
    double virtualOrigin() const { return frame_.virtualOrigin; }
    /// Kinematic momentum flux K = π R² U0² [m⁴/s²].
    double momentumFlux() const { return momentumFlux_; }

private:
    RoundLaminarProfile profile_;
    JetFrame frame_;
    double momentumFlux_ = 0;
};

} // namespace slides
