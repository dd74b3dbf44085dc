#include "slides/analysis/physics_terms.h"

#include "slides/config/scene.h"

#include <stdexcept>

namespace slides {

namespace {

/// Lift with the shear and spin parts as given.
LiftModel liftOf(bool shear, bool spin) {
    if (shear && spin) return LiftModel::saffmanMeiMagnus;
    if (shear) return LiftModel::saffmanMei;
    return spin ? LiftModel::magnus : LiftModel::none;
}

} // namespace

bool termIsOn(const Scene& scene, PhysicsTerm term) {
    const PhysicsSettings& physics = scene.physics;
    switch (term) {
    case PhysicsTerm::history: return physics.history != HistoryModel::none;
    case PhysicsTerm::addedMass: return physics.addedMass;
    case PhysicsTerm::pressureGradient: return physics.pressureGradient;
    case PhysicsTerm::shearLift: return usesShearLift(physics.lift);
    case PhysicsTerm::spinLift: return usesSpinLift(physics.lift);
    case PhysicsTerm::spin: return physics.spin;
    case PhysicsTerm::dispersion: return physics.dispersion != DispersionModel::none;
    case PhysicsTerm::heatTransfer: return physics.heatTransfer != HeatTransferModel::none;
    case PhysicsTerm::collisions: return scene.collisions.model != CollisionModel::none;
    }
    return false;
}

void setTerm(Scene& scene, PhysicsTerm term, bool on) {
    PhysicsSettings& physics = scene.physics;
    if (termIsOn(scene, term) == on) return;
    switch (term) {
    case PhysicsTerm::history:
        physics.history = on ? HistoryModel::basset : HistoryModel::none;
        return;
    case PhysicsTerm::addedMass: physics.addedMass = on; return;
    case PhysicsTerm::pressureGradient: physics.pressureGradient = on; return;
    case PhysicsTerm::shearLift: physics.lift = liftOf(on, usesSpinLift(physics.lift)); return;
    case PhysicsTerm::spinLift: physics.lift = liftOf(usesShearLift(physics.lift), on); return;
    case PhysicsTerm::spin: physics.spin = on; return;
    case PhysicsTerm::dispersion:
        physics.dispersion = on ? DispersionModel::eddyInteraction : DispersionModel::none;
        return;
    case PhysicsTerm::heatTransfer:
        physics.heatTransfer = on ? HeatTransferModel::ranzMarshall : HeatTransferModel::none;
        return;
    case PhysicsTerm::collisions:
        scene.collisions.model = on ? CollisionModel::impulse : CollisionModel::none;
        return;
    }
}

const PhysicsTermName& physicsTermRow(PhysicsTerm term) {
    static constexpr auto table = physicsTermNames();
    for (const auto& row : table)
        if (row.value == term) return row;
    throw std::logic_error("a physics term without a row in physicsTermNames()");
}

} // namespace slides
