// JetFrame: the nozzle geometry shared by the analytic jets — where a point lies relative to the
// jet, and how a 2-D similarity profile (u, v)(s, y) becomes a 3-D velocity and its gradient.
// Reference: the jet of Fig. 5.7/5.9 and Eq. 5.10/5.11 of the reference (its "core" near the
// nozzle exit); Schlichting, Boundary-Layer Theory, "plane jet" and "circular jet".
//
//     nozzle { centre (0 0 0); axis (1 0 0); radius 2e-3; crossSpanDirection (0 1 0); }
//
// Coordinates. For a point p, d = p − centre and the axial distance from the exit plane is
// a = d·axis.
//   a < 0               behind the nozzle exit plane: gas at rest, U = 0, ∇U = 0.
//   0 ≤ a < coreLength  unentrained core: the profile is frozen at its shape at s = virtualOrigin,
//                       u = u(virtualOrigin, y), v = 0; ∇U holds only the ∂u/∂y shear.
//   a ≥ coreLength      self-similar jet with the similarity coordinate
//                       s = (a − coreLength) + virtualOrigin.
// Each profile chooses virtualOrigin so that its centreline speed at s = virtualOrigin is the
// nozzle exit velocity U0: u is continuous at the core end (v jumps from 0 to v(virtualOrigin, y)
// there, and U jumps from 0 to the core profile across the exit plane).
//
// Cross-span coordinate and assembly, with e_a = axis:
//   planar        y = d·e_y (e_y = crossSpanDirection), U = u e_a + v e_y,
//                 ∇U = e_a ⊗ (∂u/∂s e_a + ∂u/∂y e_y) + e_y ⊗ (∂v/∂s e_a + ∂v/∂y e_y).
//   axisymmetric  y = r = |d − a e_a|, e_r = (d − a e_a)/r, U = u e_a + v e_r; ∇U is the planar
//                 expression with e_y → e_r plus the curvature (hoop) term
//                 (v/r)(I − e_a e_a − e_r e_r). On the axis v/r → ∂v/∂r (v is odd in r), which
//                 each profile returns in closed form (ProfileSample::vOverY), so r = 0 gives no
//                 NaN; e_r there is any unit vector ⟂ e_a (its terms vanish or are isotropic).
// gradient(i, j) = ∂U_i/∂x_j (core/vector.h).
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/parallel.h"
#include "slides/core/vector.h"

#include <span>

namespace slides {

/// Nozzle geometry (from the `nozzle {}` dictionary).
struct JetNozzle {
    Vec3 centre = Vec3::Zero();              ///< centre of the exit plane [m]
    Vec3 axis = Vec3::UnitX();               ///< unit, jet direction
    double radius = 0;                       ///< nozzle radius, or slot half-width b (planar) [m]
    Vec3 crossSpanDirection = Vec3::UnitY(); ///< unit, ⟂ axis: the y of a planar jet
};

/// How the 2-D profile is extruded: along e_a × e_y (planar) or rotated about the axis.
enum class JetGeometry { planar, axisymmetric };

// Its names: jetGeometryNames() (carrier/carrier_settings.h).

/// A self-similar profile and its first derivatives at (s, y); y ≥ 0 for axisymmetric use.
struct ProfileSample {
    double u = 0, v = 0;       ///< axial and cross-span velocity [m/s]
    double dudS = 0, dudY = 0; ///< [1/s]
    double dvdS = 0, dvdY = 0; ///< [1/s]
    double vOverY = 0;         ///< v/y, equal to ∂v/∂y at y = 0 [1/s]
};

class JetFrame {
public:
    /// Throws std::invalid_argument for a non-positive radius, a non-unit axis, a cross-span
    /// direction that is not a unit vector ⟂ axis (planar only), a negative core length or a
    /// non-positive virtual origin.
    JetFrame(const JetNozzle& nozzle, JetGeometry geometry, double coreLength,
             double virtualOrigin);

    const JetNozzle& nozzle() const { return nozzle_; }
    JetGeometry geometry() const { return geometry_; }
    double coreLength() const { return coreLength_; }
    double virtualOrigin() const { return virtualOrigin_; }

    /// Similarity coordinate s at axial distance a ≥ 0 (virtualOrigin throughout the core).
    double similarityCoordinate(double axialDistance) const {
        return axialDistance < coreLength_ ? virtualOrigin_
                                           : axialDistance - coreLength_ + virtualOrigin_;
    }

    /// U (and ∇U when needs.velocityGradient) of profile at every point; out is resized.
    /// Profile needs `ProfileSample at(double s, double y) const`, inlinable at the call site.
    template <typename Profile>
    void sample(const Profile& profile, std::span<const Vec3> points, CarrierNeeds needs,
                CarrierSample& out) const;

private:
    JetNozzle nozzle_;
    JetGeometry geometry_;
    double coreLength_;
    double virtualOrigin_;
    Mat3 transverse_; ///< I − e_a e_a
    Vec3 axisRadial_; ///< e_r used on the axis (any unit vector ⟂ e_a)
};

template <typename Profile>
void JetFrame::sample(const Profile& profile, std::span<const Vec3> points, CarrierNeeds needs,
                      CarrierSample& out) const {
    out.resize(points.size(), needs);
    const Vec3& axis = nozzle_.axis;
    const bool planar = geometry_ == JetGeometry::planar;
    const auto count = static_cast<std::ptrdiff_t>(points.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const Vec3 offset = points[i] - nozzle_.centre;
        const double axial = offset.dot(axis);
        if (axial < 0) { // behind the exit plane: at rest
            out.velocity[i].setZero();
            if (needs.velocityGradient) out.velocityGradient[i].setZero();
            continue;
        }
        const bool inCore = axial < coreLength_;
        const double s = inCore ? virtualOrigin_ : axial - coreLength_ + virtualOrigin_;
        Vec3 across;
        double y;
        if (planar) {
            across = nozzle_.crossSpanDirection;
            y = offset.dot(across);
        } else {
            const Vec3 radial = offset - axial * axis;
            y = radial.norm();
            across = y > 0 ? Vec3(radial / y) : axisRadial_;
        }
        ProfileSample p = profile.at(s, y);
        if (inCore) p = ProfileSample{p.u, 0.0, 0.0, p.dudY, 0.0, 0.0, 0.0}; // frozen, v = 0
        out.velocity[i] = p.u * axis + p.v * across;
        if (!needs.velocityGradient) continue;
        Mat3& gradient = out.velocityGradient[i];
        gradient.noalias() = axis * (p.dudS * axis + p.dudY * across).transpose();
        gradient.noalias() += across * (p.dvdS * axis + p.dvdY * across).transpose();
        if (!planar) gradient += p.vOverY * (transverse_ - across * across.transpose());
    }
}

} // namespace slides
