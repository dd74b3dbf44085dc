// Collision settings: the particle–particle model, and how a surface meets a particle.
//
//     collisions
//     {
//         model       impulse;     // none | impulse (collide-and-stream, Eq. 2.34–2.58)
//         restitution { model velocityDependent; yieldPressureFactor 3; }
//         friction    { static 0.3; dynamic 0.3; }
//     }
//     surfaces { target { type plane; ... interaction deposit; } }   // absorb | rebound | deposit
//
// How to add a model: an enumerator, its name in the table, its case where ParticleCollisions
// resolves a contact (collide/particle_collisions.cpp).
#pragma once

#include "slides/collide/impulse.h"
#include "slides/physics/restitution.h"

#include <array>
#include <string_view>

namespace slides {

enum class CollisionModel { none, impulse };

struct CollisionModelName {
    CollisionModel value;
    std::string_view name;
};

constexpr std::array<CollisionModelName, 2> collisionModelNames() {
    return {{{CollisionModel::none, "none"}, {CollisionModel::impulse, "impulse"}}};
}

/// What a surface does to a particle that reaches it.
enum class SurfaceInteraction {
    absorb,  ///< records the arrival and removes the particle (a sink, as OpenFOAM's stick)
    rebound, ///< impulse law with restitution and friction (Eq. 2.15–2.33)
    deposit  ///< sticks when Eq. 5.9 holds, else rebounds; the deposit then collides too
};

struct SurfaceInteractionName {
    SurfaceInteraction value;
    std::string_view name;
};

constexpr std::array<SurfaceInteractionName, 3> surfaceInteractionNames() {
    return {{{SurfaceInteraction::absorb, "absorb"},
             {SurfaceInteraction::rebound, "rebound"},
             {SurfaceInteraction::deposit, "deposit"}}};
}

/// Contact laws of every impulse contact: between particles, with surfaces and the deposit.
struct CollisionSettings {
    CollisionModel model = CollisionModel::none; ///< particle–particle collisions
    RestitutionSettings restitution;
    FrictionSettings friction;
};

} // namespace slides
