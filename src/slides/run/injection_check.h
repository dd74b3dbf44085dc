// Injection check: particles start inside the carrier's mesh and the domain box.
//
// Particles injected outside either escape at once, so a case whose nozzle disc or lattice is
// partly outside is refused. The disc is sampled at points spread evenly over its area; on a
// 2-D mesh (one cell thick between `empty` patches) the disc becomes the slot's line in the
// plane. A lattice is checked at the sites its particles take, each injector of `injectors {}`
// on its disc (its centre when a point) or at its file's rows.
//
//     nozzle { centre (0 0 0); axis (1 0 0); radius 2e-3; }
//     injection { mode lattice; latticeCoeffs { origin (0 0 0); spacing 1e-4; sites (10 10 10); } }
#pragma once

#include "slides/config/scene.h"

namespace slides {

/// Throws InputError at nozzle.radius (or injection.latticeCoeffs.origin, or each injector's
/// radius or file) when points where particles start lie outside the carrier's mesh or
/// scene.domain, saying which share does.
void requireInjectionInside(const Scene& scene, const CarrierField& carrier);

} // namespace slides
