// PlaneConstraint: particles of a 2-D carrier (a mesh one cell thick between `empty` patches)
// held in its plane, as OpenFOAM holds parcels of a 2-D case (particle::constrainToMeshCentre,
// particle::constrainDirection): the cross-plane coordinate fixed at the mesh's mid-plane, every
// vector out of the plane removed. Reference: OpenFOAM src/lagrangian/basic/particle/particleI.H.
//
//     (no key: on exactly when CarrierField::planeNormal() gives a plane)
//
// The stepper applies it after every stage that can leave the plane (injection, the eddy's
// drawn fluctuation, the stream step, collisions and surfaces), so fluctuations, lift, gravity,
// contacts and rebounds act in the plane only; spin, a rotation in the plane, keeps only its
// component along the normal.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/particle_cloud.h"

#include <optional>
#include <vector>

namespace slides {

class PlaneConstraint {
public:
    /// The plane of unit normal `normal` through the middle of `bounds` along it.
    PlaneConstraint(const Vec3& normal, const Box& bounds);

    /// Every particle moved to the mid-plane, its velocity, eddy fluctuation and contact force
    /// into the plane, its spin and contact torque onto the normal.
    void hold(ParticleCloud& cloud) const;
    /// Removes the cross-plane component of each vector (a sampled gas velocity with its eddy
    /// fluctuation).
    void project(std::vector<Vec3>& vectors) const;

    /// Where hold puts a particle at point: on the mid-plane (its in-plane part plus the
    /// mid-plane's offset, exact for a normal along an axis).
    Vec3 onMidPlane(const Vec3& point) const { return inPlane(point) + midPlane_ * normal_; }

    const Vec3& normal() const { return normal_; }
    /// The mid-plane's offset along the normal, x·n [m].
    double midPlane() const { return midPlane_; }

private:
    Vec3 inPlane(const Vec3& v) const { return v - v.dot(normal_) * normal_; }
    Vec3 alongNormal(const Vec3& v) const { return v.dot(normal_) * normal_; }

    Vec3 normal_;
    double midPlane_;
};

/// The constraint of a 2-D carrier, none for a 3-D or analytic one.
std::optional<PlaneConstraint> planeConstraintOf(const CarrierField& carrier);

} // namespace slides
