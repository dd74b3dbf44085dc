// PhysicsTerm: the name table of the physics terms a dictionary may leave to the scene analysis
// (`auto`), and the record of one left to it; analysis/physics_terms.h decides and sets them.
//
//     physics { history { model auto; } addedMass auto; lift auto; spin auto; }
//     collisions { model auto; }
#pragma once

#include <array>
#include <string>
#include <string_view>

namespace slides {

enum class PhysicsTerm {
    history,          ///< Basset history force (Eq. 3.3)
    addedMass,        ///< added mass C_A = 1/2 (Eq. 3.3)
    pressureGradient, ///< undisturbed-flow force m_f DU/Dt (Eq. 3.3)
    shearLift,        ///< Saffman–Mei lift (Sec. 3.4)
    spinLift,         ///< Magnus lift (Sec. 3.4); needs spin
    spin,             ///< viscous torque on the spinning sphere (Eq. 3.18)
    dispersion,       ///< turbulent eddies (Sec. 3.9)
    heatTransfer,     ///< convective heating (Sec. 3.8)
    collisions        ///< particle–particle impulses (Eq. 2.34–2.58)
};

struct PhysicsTermName {
    PhysicsTerm value;
    std::string_view name;    ///< in the decision table and summary.json
    std::string_view key;     ///< the dictionary key that switches it
    std::string_view onModel; ///< the model auto turns on
};

/// The name table of the terms. How to add one: an enumerator, its row here, its case in
/// setTerm() and termIsOn() (analysis/physics_terms.cpp) and its estimate in
/// analysis/term_estimates.h.
constexpr std::array<PhysicsTermName, 9> physicsTermNames() {
    return {
        {{PhysicsTerm::history, "history", "physics.history.model", "basset"},
         {PhysicsTerm::addedMass, "addedMass", "physics.addedMass", "on"},
         {PhysicsTerm::pressureGradient, "pressureGradient", "physics.pressureGradient", "on"},
         {PhysicsTerm::shearLift, "saffmanMeiLift", "physics.lift", "saffmanMei"},
         {PhysicsTerm::spinLift, "magnusLift", "physics.lift", "magnus"},
         {PhysicsTerm::spin, "spin", "physics.spin", "on"},
         {PhysicsTerm::dispersion, "dispersion", "physics.dispersion.model", "eddyInteraction"},
         {PhysicsTerm::heatTransfer, "heatTransfer", "physics.heatTransfer.model", "ranzMarshall"},
         {PhysicsTerm::collisions, "collisions", "collisions.model", "impulse"}}};
}

/// A term the dictionary left to the analysis (`auto`).
struct AutomaticTerm {
    PhysicsTerm term;
    /// Why it cannot be turned on (an input it needs that the dictionary lacks, e.g.
    /// "needs particles.specificHeat"); empty when it can.
    std::string unavailable;
};

} // namespace slides
