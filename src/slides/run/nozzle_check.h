// Nozzle check: the injection disc lies inside the carrier's mesh and the domain box.
//
// Particles injected outside either escape at once, so a case whose disc is partly outside is
// refused. The disc is sampled at points spread evenly over its area; on a 2-D mesh (one cell
// thick between `empty` patches) the disc becomes the slot's line in the plane.
//
//     nozzle { centre (0 0 0); axis (1 0 0); radius 2e-3; }
#pragma once

#include "slides/config/scene.h"

namespace slides {

/// Throws InputError at nozzle.radius when sample points of the injection disc lie outside the
/// carrier's mesh or scene.domain, saying which share of them does.
void requireNozzleDiscInside(const Scene& scene, const CarrierField& carrier);

} // namespace slides
