// Particle order: the cloud's particles kept in memory in the order of their carrier location.
//
// A mesh carrier's location is a tetrahedron index (carrier/foam_locator.h), numbered face by
// face, and OpenFOAM numbers faces by owner cell: particles ordered by location read the mesh's
// cell, face and point data nearly in order, so a batch's walks and interpolations hit the cache
// (DESIGN.md "Speed"). The order is ascending (location, id): it depends on nothing but the
// particles, so results stay independent of the thread count, and a run that restarts from a
// checkpoint (which keeps the cloud's order and the step count) reorders at the same steps as an
// uninterrupted one. Particle ids stay; the order in which particles arrive, and so their order
// in the outputs, follows the memory order.
#pragma once

#include "slides/core/particle_cloud.h"

namespace slides {

/// Steps between reorders, chosen by measurement (tools/bench/foam-jet, 1e4 particles of 10 and
/// 50 µm, process CPU, min of 2 interleaved runs): per particle-step 0.98, 0.85, 0.93 and 0.96
/// times the cost without reordering, every 1, 5, 20 and 100 steps.
inline constexpr long particleOrderInterval = 5;

/// Orders every array of cloud (ParticleCloud::forEachArray, and modelState) by ascending
/// (carrierLocation, id) when step is a multiple of particleOrderInterval and the cloud keeps
/// locations; otherwise leaves it as it is.
void orderByLocation(ParticleCloud& cloud, long step);

} // namespace slides
