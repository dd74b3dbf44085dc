// JetFrame: where a point lies relative to a jet — the similarity coordinate along the axis,
// the cross-span coordinate, and how a 2-D profile (u, v)(s, y) becomes a 3-D field.
//
// Along the axis, the nozzle exit is followed by an unentrained core of length coreLength in
// which the profile is frozen at its shape at s = virtualOrigin and there is no entrainment
// (v = 0). Beyond it the self-similar profile holds with s = a − coreLength + virtualOrigin,
// a the axial distance from the nozzle exit; virtualOrigin is chosen by each profile so the
// centreline speed there is the exit velocity U0, so u is continuous at the core end. Behind
// the nozzle exit plane (a < 0) the gas is at rest.
//
// planar: y = d·e_y (the cross-span direction), U = u e_a + v e_y.
// axisymmetric: y = r, U = u e_a + v e_r, and the gradient gains the curvature term
// (v/r)(I − e_a e_a − e_r e_r), whose limit on the axis is (∂v/∂r)(I − e_a e_a).
//
//     nozzle { centre (0 0 0); axis (1 0 0); radius 2e-3; crossSpanDirection (0 1 0); }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/config/scene.h"

namespace slides {

/// A self-similar jet profile and its derivatives at (s, y); y ≥ 0 for axisymmetric use.
struct ProfileSample {
    double u = 0, v = 0;       ///< axial and cross-span velocity [m/s]
    double dudS = 0, dudY = 0; ///< [1/s]
    double dvdS = 0, dvdY = 0; ///< [1/s]
};

struct JetFrame {
    NozzleSettings nozzle;
    JetProfileKind geometry = JetProfileKind::axisymmetric;
    double coreLength = 0;    ///< [m]
    double virtualOrigin = 0; ///< s at the end of the core [m]

    /// Samples U (and its gradient if asked) of profile at every point.
    template <typename Profile>
    void sample(const Profile& profile, std::span<const Vec3> points, CarrierNeeds needs,
                CarrierSample& out) const;
};

template <typename Profile>
void JetFrame::sample(const Profile& profile, std::span<const Vec3> points, CarrierNeeds needs,
                      CarrierSample& out) const {
    out.resize(points.size(), needs);
    const Vec3& axis = nozzle.axis;
    const Mat3 transverse = Mat3::Identity() - axis * axis.transpose();
    for (std::size_t i = 0; i < points.size(); ++i) {
        const Vec3 offset = points[i] - nozzle.centre;
        const double axial = offset.dot(axis);
        if (axial < 0) {
            out.velocity[i].setZero();
            if (needs.velocityGradient) out.velocityGradient[i].setZero();
            continue;
        }
        const bool inCore = axial < coreLength;
        const double s = inCore ? virtualOrigin : axial - coreLength + virtualOrigin;
        Vec3 across;
        double y;
        if (geometry == JetProfileKind::planar) {
            across = nozzle.crossSpanDirection;
            y = offset.dot(across);
        } else {
            const Vec3 radial = offset - axial * axis;
            y = radial.norm();
            // On the axis e_r is undefined but v = 0 there; any transverse direction will do.
            across = y > 0 ? Vec3(radial / y) : nozzle.crossSpanDirection;
        }
        ProfileSample p = profile.at(s, y);
        if (inCore) p = {p.u, 0.0, 0.0, p.dudY, 0.0, 0.0}; // frozen, no entrainment
        out.velocity[i] = p.u * axis + p.v * across;
        if (!needs.velocityGradient) continue;
        Mat3& gradient = out.velocityGradient[i];
        gradient = axis * (p.dudS * axis + p.dudY * across).transpose() +
                   across * (p.dvdS * axis + p.dvdY * across).transpose();
        if (geometry == JetProfileKind::axisymmetric) {
            // v/r → ∂v/∂r on the axis (v is odd in r).
            const double hoopRate = y > 1e-12 * s ? p.v / y : p.dvdY;
            gradient += hoopRate * (transverse - across * across.transpose());
        }
    }
}

} // namespace slides
