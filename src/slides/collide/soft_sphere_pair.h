// Soft-sphere contact load of a sphere pair or a sphere and a plane wall: force and torques
// from the normal and tangential laws of physics/soft_contact.h, for a DEM step loop.
//
// Reference: Section 2.2 of the reference (Eq. 2.4–2.14), forms of LIGGGHTS `hertz` +
// `tangential history`. The torques act at the contact point on the plane of the overlap
// lens (distance (d² + R1² − R2²)/(2d) from the first centre, d from a wall), so the lever
// arms add up to the centre distance and a pair conserves angular momentum exactly.
//
//     particles { material { bulkModulus 1.6e11; shearModulus 8.0e10; } }
#pragma once

#include "slides/physics/soft_contact.h"

namespace slides {

/// The kinematic state of one sphere in a contact.
struct ContactSphere {
    Vec3 position = Vec3::Zero();
    Vec3 velocity = Vec3::Zero();
    Vec3 spin = Vec3::Zero(); ///< angular velocity ω [rad/s]
    double radius = 0;        ///< [m]
};

/// What a contact does to its bodies over the step; all zero when they do not touch.
struct ContactLoad {
    double overlap = 0;                 ///< δ [m], ≤ 0 when apart
    Vec3 force = Vec3::Zero();          ///< on the first body; the second gets −force [N]
    Vec3 torqueOnFirst = Vec3::Zero();  ///< [N m]
    Vec3 torqueOnSecond = Vec3::Zero(); ///< [N m]
    /// Power the contact turns into heat [W] (Eq. 2.113: the work of its dissipative parts):
    /// (F_n − F_el) dδ/dt of the normal damping (and of the no-pull clamp), γ_t v_t² while the
    /// tangential spring sticks, −F_t·v_t while it slides at the Coulomb limit.
    double dissipatedPower = 0;
    /// Heat flowing into the first body from the second [W] (Eq. 2.118; set by the caller).
    double conductedPower = 0;
};

/// Load of sphere a on sphere b (force on a). The spring is that pair's; it is reset when the
/// spheres separate. In the step where they part (apart now, the spring's δ_max > 0 from the
/// last load), the load is the dashpot's pull up to the parting (partingNormalForce).
ContactLoad sphereSphereLoad(const ContactPair& pair, const SoftContactLaw& law,
                             const ContactSphere& a, const ContactSphere& b,
                             TangentialSpring& spring, double dt);

/// Load of a resting plane wall (point p, unit normal n into the gas) on the sphere; the spring
/// as in sphereSphereLoad.
ContactLoad sphereWallLoad(const ContactPair& pair, const SoftContactLaw& law,
                           const ContactSphere& sphere, const Vec3& wallPoint,
                           const Vec3& wallNormal, TangentialSpring& spring, double dt);

} // namespace slides
