// Collision settings: the particle–particle model, and how a surface meets a particle.
//
//     collisions
//     {
//         model       impulse;     // none | impulse (collide-and-stream, Eq. 2.34–2.58)
//                                  // | softSphere (Hertz–Mindlin forces, Eq. 2.4–2.14)
//         restitution { model velocityDependent; yieldPressureFactor 3; }
//         friction    { static 0.3; dynamic 0.3; regularisation none; slipSpeed 1e-3; }
//         softSphereCoeffs { damping restitution; neighbourSkin 0.2; contactLaw hertz; }
//     }
//     surfaces { target { type plane; ... interaction deposit; } }   // absorb | rebound | deposit
//                                                                    // | erode
//
// How to add a model: an enumerator, its name in the table, and the stage of the stepper that
// resolves its contacts (run/stepper.cpp: ParticleCollisions for impulses,
// SoftSphereCollisions for forces).
#pragma once

#include "slides/collide/impulse.h"
#include "slides/physics/contact_conduction.h"
#include "slides/physics/restitution.h"

#include <array>
#include <string_view>

namespace slides {

enum class CollisionModel { none, impulse, softSphere };

struct CollisionModelName {
    CollisionModel value;
    std::string_view name;
};

constexpr std::array<CollisionModelName, 3> collisionModelNames() {
    return {{{CollisionModel::none, "none"},
             {CollisionModel::impulse, "impulse"},
             {CollisionModel::softSphere, "softSphere"}}};
}

/// How a soft-sphere contact's damping ratio β follows from the restitution coefficient.
enum class SoftSphereDamping {
    restitution, ///< β solved so that a Hertz impact restitutes exactly e (softContactLaw)
    tsuji        ///< β = ln e/√(ln²e + π²), LIGGGHTS' choice (restitutes a little more)
};

struct SoftSphereDampingName {
    SoftSphereDamping value;
    std::string_view name;
};

constexpr std::array<SoftSphereDampingName, 2> softSphereDampingNames() {
    return {{{SoftSphereDamping::restitution, "restitution"}, {SoftSphereDamping::tsuji, "tsuji"}}};
}

/// The soft-sphere model's settings (collide/soft_sphere_collisions.h).
struct SoftSphereSettings {
    SoftSphereDamping damping = SoftSphereDamping::restitution;
    double neighbourSkin = 0.2; ///< Verlet-list skin per largest particle radius
    NormalContactLaw contactLaw = NormalContactLaw::hertz; ///< physics/contact_laws.h
    double normalStiffness = 0; ///< k of linearSpringDashpot, k_L of waltonBraun [N/m]
    double dissipativeTime = 0; ///< A of viscoelasticHertz [s]
};

/// What a surface does to a particle that reaches it.
enum class SurfaceInteraction {
    absorb,  ///< records the arrival and removes the particle (a sink, as OpenFOAM's stick)
    rebound, ///< impulse law with restitution and friction (Eq. 2.15–2.33)
    deposit, ///< sticks when Eq. 5.9 holds, else rebounds; the deposit then collides too
    erode    ///< rebounds, and loads a porous layer's damage grid (Section 5.2)
};

struct SurfaceInteractionName {
    SurfaceInteraction value;
    std::string_view name;
};

constexpr std::array<SurfaceInteractionName, 4> surfaceInteractionNames() {
    return {{{SurfaceInteraction::absorb, "absorb"},
             {SurfaceInteraction::rebound, "rebound"},
             {SurfaceInteraction::deposit, "deposit"},
             {SurfaceInteraction::erode, "erode"}}};
}

/// Contact laws of every impulse contact: between particles, with surfaces and the deposit.
struct CollisionSettings {
    CollisionModel model = CollisionModel::none; ///< particle–particle collisions
    RestitutionSettings restitution;
    FrictionSettings friction;
    SoftSphereSettings softSphere;
    /// Contacts heat their particles by the energy they dissipate (Eq. 2.117), when
    /// temperatures are tracked (physics.heatTransfer).
    bool heating = true;
    /// Heat conducted between touching soft spheres (physics/contact_conduction.h).
    ContactConductionSettings conduction;
};

/// The soft-sphere contact law of the settings: the normal law with its constants, the damping
/// that restitutes e (hertz: β of softContactLaw or Tsuji's), the Coulomb limit μ_d and its
/// regularisation.
inline SoftContactLaw softContactLawOf(const CollisionSettings& collisions) {
    const double e = collisions.restitution.coefficient;
    const FrictionSettings& friction = collisions.friction;
    const SoftSphereSettings& softSphere = collisions.softSphere;
    SoftContactLaw law{.friction = friction.dynamicCoefficient,
                       .normalLaw = softSphere.contactLaw,
                       .normalStiffness = softSphere.normalStiffness,
                       .restitution = e,
                       .dissipativeTime = softSphere.dissipativeTime,
                       .regularisation = friction.regularisation,
                       .regularisationSpeed = friction.regularisationSpeed};
    if (softSphere.contactLaw == NormalContactLaw::hertz)
        law.dampingRatio = softSphere.damping == SoftSphereDamping::tsuji
                               ? liggghtsDampingRatio(e)
                               : softContactLaw(e, 0).dampingRatio;
    return law;
}

/// Temperature rise [K] of bodies of total heat capacity Σ c m [J/K] sharing the kinetic energy
/// a contact dissipated (Eq. 2.115–2.117: all dissipated work becomes heat, ΔH = Δ(KE)).
/// A pair shares it by heat capacity, so both warm alike; a rigid wall or the static deposit
/// takes none.
inline double collisionalTemperatureRise(double dissipatedEnergy, double heatCapacity) {
    return dissipatedEnergy / heatCapacity;
}

/// Whether a surface of this interaction meets particles by soft-sphere forces (a rebound wall
/// under the softSphere model) rather than by the impulse law at the touch.
inline bool meetsBySoftContact(const CollisionSettings& collisions,
                               SurfaceInteraction interaction) {
    return collisions.model == CollisionModel::softSphere &&
           interaction == SurfaceInteraction::rebound;
}

} // namespace slides
