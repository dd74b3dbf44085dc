// PhysicsTerm: the physics terms a dictionary may leave to the scene analysis with `auto`.
//
// Each term is switched by one dictionary key, whose value `auto` (the default) lets the scene
// analysis (analysis/scene_analysis.h) turn it on where its estimated effect reaches
// physics.autoThreshold; a term turned on by auto takes its family's first model (the name
// below). A term that is off costs nothing in the step loop and allocates nothing.
//
//     physics { history { model auto; } addedMass auto; lift auto; spin auto; }
//     collisions { model auto; }
#pragma once

#include "slides/physics/physics_term.h"

namespace slides {

struct Scene;

/// Whether the term is on in the scene.
bool termIsOn(const Scene& scene, PhysicsTerm term);

/// Turns the term on (with its family's auto model, the one already chosen if on) or off.
void setTerm(Scene& scene, PhysicsTerm term, bool on);

const PhysicsTermName& physicsTermRow(PhysicsTerm term);

} // namespace slides
