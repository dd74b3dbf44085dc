// SimilarityJet: what the analytic jets share — a steady self-similar profile (u, v)(s, y) placed
// by a JetFrame, its centreline speed and half-width along the jet. Reference: Eq. 5.10/5.11 of
// the reference (carrier/analytic_jet.h); Schlichting, Boundary-Layer Theory, "plane jet" and
// "circular jet" (carrier/round_laminar_jet.h).
//
//     carrier { type analyticJet; ... }   or   carrier { type roundLaminarJet; ... }
//
// Profile needs `ProfileSample at(double s, double y) const` (JetFrame::sample), and at the
// similarity coordinate s: `centrelineVelocity(s)` [m/s], `halfWidth(s)` [m], the y where
// u = u_centre/2, `virtualOrigin(U0)` [m], the s where the centreline speed is U0, and
// `travelTime(from, to)` [s], ∫_from^to ds/u_c(s) in closed form (carrier/pulsed_jet.h).
#pragma once

#include "slides/carrier/jet_frame.h"

#include <algorithm>

namespace slides {

template <typename Profile> class SimilarityJet : public CarrierField {
public:
    void sample(std::span<const Vec3> points, double /*time: steady*/, CarrierNeeds needs,
                CarrierSample& out) const override {
        frame_.sample(profile_, points, needs, out);
    }

    const Profile& profile() const { return profile_; }
    const JetFrame& frame() const { return frame_; }
    double virtualOrigin() const { return frame_.virtualOrigin(); } ///< s0 [m]
    /// Centreline speed at axial distance a from the exit plane: 0 behind it, U0 in the core,
    /// the profile's beyond [m/s].
    double centrelineVelocity(double axialDistance) const {
        if (axialDistance < 0) return 0;
        return profile_.centrelineVelocity(frame_.similarityCoordinate(axialDistance));
    }
    /// Time the centreline flow takes from the exit plane to axial distance a ≥ 0,
    /// τ(a) = ∫_0^a da'/u_c(a'): a/U0 through the core, then the profile's closed form (0 at
    /// a < 0, where the gas is at rest) [s]. Its derivative is 1/centrelineVelocity(a).
    double travelTime(double axialDistance) const {
        if (axialDistance < 0) return 0;
        const double core = frame_.coreLength();
        const double origin = frame_.virtualOrigin();
        const double exitSpeed = profile_.centrelineVelocity(origin);
        if (axialDistance < core) return axialDistance / exitSpeed;
        return core / exitSpeed +
               profile_.travelTime(origin, frame_.similarityCoordinate(axialDistance));
    }
    /// Half-width where u = u_centre/2, at axial distance a ≥ 0 (the core's at a < 0) [m].
    double halfWidth(double axialDistance) const {
        return profile_.halfWidth(frame_.similarityCoordinate(std::max(axialDistance, 0.0)));
    }

protected:
    /// The frame's virtual origin is where the profile's centreline speed is nozzleVelocity.
    SimilarityJet(const Profile& profile, const JetNozzle& nozzle, JetGeometry geometry,
                  double coreLength, double nozzleVelocity)
        : profile_(profile),
          frame_(nozzle, geometry, coreLength, profile_.virtualOrigin(nozzleVelocity)) {}

private:
    Profile profile_;
    JetFrame frame_;
};

} // namespace slides
