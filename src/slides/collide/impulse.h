// Impulse–momentum resolution of one contact (collide step of collide-and-stream): the
// post-impact velocities and spins of two spheres, or of a sphere and a rigid body.
//
// Reference: Section 2.3 of the reference, Eq. 2.15–2.58, in vector form. With n̂ the unit
// normal from body b to body a at the contact and v_rel = v_pa − v_pb the relative velocity
// of the contact points (Eq. 2.35, v_p = v + ω × r_cp):
//   normal impulse on a   J_n = −(1 + e) m* (v_rel · n̂) n̂                (Eq. 2.23–2.25, 2.46)
//   stick impulse         J_t = −(2/7) m* v_rel,t   (slip brought to zero:
//   Eq. 2.27–2.29, 2.55–2.56;
//                         2/7 = 1/(1 + 5/2) for I = (2/5) m R²)
//   Coulomb limit         |J_t| ≤ μ_s |J_n|, else J_t = −μ_d |J_n| t̂        (Eq. 2.30–2.31)
//   a: Δv = (J_n + J_t)/m_a, Δω = r_a × J_t / I_a; b the opposite impulse (Eq. 2.57–2.58).
// The external forces during the contact are left to the stream step, as the collide step is
// much shorter than it (the ⟨F^e⟩δt terms of Eq. 2.25 and 2.47 vanish with δt). A rigid body
// (wall, deposit) has zero inverse mass and inertia, so m* = m_a. Linear momentum is exchanged
// by one impulse, hence conserved to round-off; angular momentum about the contact point too.
//
//     collisions { friction { static 0.3; dynamic 0.25; } }
#pragma once

#include "slides/core/vector.h"
#include "slides/physics/regularised_friction.h"

namespace slides {

struct FrictionSettings {
    double staticCoefficient = 0.3;  ///< μ_s
    double dynamicCoefficient = 0.3; ///< μ_d
    /// Of soft-sphere contacts: the Mindlin spring (none) or a regularised Coulomb law
    /// (physics/regularised_friction.h) over the slip speed ε.
    FrictionRegularisation regularisation = FrictionRegularisation::none;
    double regularisationSpeed = 1e-3; ///< ε [m/s]
};

/// The velocities of one body at a contact; a rigid body has inverseMass = 0.
struct ImpactBody {
    Vec3 velocity = Vec3::Zero();        ///< [m/s]
    Vec3 angularVelocity = Vec3::Zero(); ///< [rad/s]
    double inverseMass = 0;              ///< 1/m [1/kg]
    double radius = 0;                   ///< centre to contact point [m]
};

/// The impulse on body a (b receives its opposite), for normal n̂ pointing from b to a and
/// restitution e. Returns a zero impulse when the bodies separate already.
inline Vec3 contactImpulse(const ImpactBody& a, const ImpactBody& b, const Vec3& normal,
                           double restitution, const FrictionSettings& friction) {
    // Contact points: a's at −R_a n̂ from its centre, b's at +R_b n̂ (Eq. 2.35).
    const Vec3 contactVelocityA = a.velocity + a.angularVelocity.cross(-a.radius * normal);
    const Vec3 contactVelocityB = b.velocity + b.angularVelocity.cross(b.radius * normal);
    const Vec3 relative = contactVelocityA - contactVelocityB;
    const double approach = relative.dot(normal);
    if (approach >= 0) return Vec3::Zero();
    const double effectiveMass = 1.0 / (a.inverseMass + b.inverseMass);
    const Vec3 normalImpulse = -(1 + restitution) * effectiveMass * approach * normal;
    const Vec3 slip = relative - approach * normal;
    Vec3 tangentialImpulse = -(2.0 / 7.0) * effectiveMass * slip;
    const double limit = friction.staticCoefficient * normalImpulse.norm();
    const double stickImpulse = tangentialImpulse.norm();
    if (stickImpulse > limit)
        tangentialImpulse *= friction.dynamicCoefficient * normalImpulse.norm() / stickImpulse;
    return normalImpulse + tangentialImpulse;
}

/// Kinetic energy ½ m v² + ½ I ω² of a body (zero for a rigid one, which does not move) [J].
inline double kineticEnergy(const ImpactBody& body) {
    if (body.inverseMass == 0) return 0;
    const double mass = 1 / body.inverseMass;
    return 0.5 * mass *
           (body.velocity.squaredNorm() +
            0.4 * body.radius * body.radius * body.angularVelocity.squaredNorm());
}

/// Applies impulse J to body a and −J to body b at their contact points (Eq. 2.57–2.58).
inline void applyImpulse(ImpactBody& a, ImpactBody& b, const Vec3& normal, const Vec3& impulse) {
    const auto apply = [](ImpactBody& body, const Vec3& arm, const Vec3& j) {
        body.velocity += body.inverseMass * j;
        // I = (2/5) m R², so 1/I = (5/2) (1/m) / R².
        if (body.radius > 0)
            body.angularVelocity +=
                2.5 * body.inverseMass / (body.radius * body.radius) * arm.cross(j);
    };
    apply(a, -a.radius * normal, impulse);
    apply(b, b.radius * normal, -impulse);
}

} // namespace slides
