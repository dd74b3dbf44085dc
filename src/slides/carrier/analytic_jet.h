// AnalyticJet: the sech² jet of Eq. 5.10/5.11 of the reference — Bickley's planar laminar jet
// (Schlichting, Boundary-Layer Theory, "plane jet"), planar or used axisymmetrically (y → r).
//
//   u = C1 s^(−1/3) sech²η,   v = C2 s^(−2/3) [2η sech²η − tanh η],   η = C3 y / s^(2/3)
//
// (the PDF text of Eq. 5.11 lost the y in the first term). Continuity fixes C2: the stream
// function ψ = (C1/C3) s^(1/3) tanh η gives u = ∂ψ/∂y and v = −∂ψ/∂s with C2 = C1/(3 C3).
// From the kinematic momentum flux K = J/ρ = 2 R U0² of a slot of half-width R and the
// viscosity ν: C1 = (3K²/(32ν))^(1/3), C3 = (K/(48ν²))^(1/3), C2 = (Kν/6)^(1/3)
// (Schlichting's 0.4543, 0.2752, 0.5503 are the cube roots of 3/32, 1/48, 1/6). The virtual
// origin, where the centreline speed C1 s^(−1/3) equals U0, is s0 = (C1/U0)³. The
// axisymmetric use does not conserve mass exactly in 3-D (it is the reference's model);
// roundLaminarJet does.
//
//     carrier { type analyticJet;
//               analyticJetCoeffs { profile axisymmetric; nozzleVelocity 25; coreLength 8e-3;
//                                   effectiveViscosity 1.4e-3; /* or C1 7.48; C3 29.8; */ } }
#pragma once

#include "slides/carrier/jet_frame.h"

namespace slides {

/// Eq. 5.10/5.11 and their derivatives.
struct BickleyProfile {
    double C1 = 0, C2 = 0, C3 = 0;
    ProfileSample at(double s, double y) const;
};

class AnalyticJet : public CarrierField {
public:
    /// Throws std::invalid_argument when an explicit C2 contradicts continuity (the scene
    /// reader reports that as an input error first).
    AnalyticJet(const NozzleSettings& nozzle, const CarrierSettings& settings);

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override;
    std::string describe() const override;

    const BickleyProfile& profile() const { return profile_; }
    double virtualOrigin() const { return frame_.virtualOrigin; }
    /// Centreline speed at axial distance a ≥ 0 from the nozzle exit [m/s].
    double centrelineVelocity(double axialDistance) const;

private:
    BickleyProfile profile_;
    JetFrame frame_;
};

} // namespace slides
