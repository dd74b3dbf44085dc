// Particle order: the cloud's particles kept in memory in the order in which the step reads the
// data around them, every few steps.
//
// - By carrier location: a mesh carrier's location is a tetrahedron index
//   (carrier/foam_locator.h), numbered face by face, and OpenFOAM numbers faces by owner cell:
//   particles ordered by location read the mesh's cell, face and point data nearly in order, so
//   a batch's walks and interpolations hit the cache (DESIGN.md "Speed").
// - By contact cell (collide/soft_sphere_collisions.h, cellOrder): neighbours in space are then
//   neighbours in memory, so each thread's share of the particles is also its share of the
//   contacts. On two cores whose caches do not share a level, data written by one thread and
//   read by the other costs a transfer between the caches each time; a loop over 10⁵ particles
//   after the other thread had read them ran 2.5 times slower than after its own thread had.
//
// Either order depends on nothing but the particles, so results stay independent of the thread
// count, and a run that restarts from a checkpoint (which keeps the cloud's order and the step
// count) reorders at the same steps as an uninterrupted one. Particle ids stay; the order in
// which particles arrive, and so their order in the outputs, follows the memory order.
#pragma once

#include "slides/core/parallel.h"
#include "slides/core/particle_cloud.h"

#include <cstdint>
#include <span>
#include <vector>

namespace slides {

/// Steps between reorders by location, chosen by measurement (tools/bench/foam-jet, 1e4
/// particles of 10 and 50 µm, process CPU, min of 2 interleaved runs): per particle-step 0.98,
/// 0.85, 0.93 and 0.96 times the cost without reordering, every 1, 5, 20 and 100 steps.
inline constexpr long particleOrderInterval = 5;

/// Steps between reorders by contact cell, the first at the first step (a later one makes the
/// neighbour list be built again). Measured on tools/bench/granular-gas's scene, two threads,
/// interleaved runs: over 1000 steps, every 100 steps cost 2.6 % more than every 500; over 5000,
/// every 1000 was within the noise of reordering at the first step only (and 0.85 times the
/// time of the build before any reordering, whose loaded particles were listed serially).
/// (LIGGGHTS sorts its atoms every 1000 steps by default.)
inline constexpr long cellOrderInterval = 1000;

/// Orders every array of cloud (ParticleCloud::forEachArray, and modelState) by ascending
/// (carrierLocation, id) when step is a multiple of particleOrderInterval and the cloud keeps
/// locations; otherwise leaves it as it is.
void orderByLocation(ParticleCloud& cloud, long step);

/// Moves every array of cloud (ParticleCloud::forEachArray, and modelState) so that the
/// particle at index order[k] comes to index k; order is a permutation of the indices.
void reorderParticles(ParticleCloud& cloud, std::span<const std::uint32_t> order);

/// The same for one array of one entry a particle (a stage's own, beside the cloud).
template <typename T>
void reorderParticleArray(std::vector<T>& array, std::span<const std::uint32_t> order) {
    const auto count = static_cast<std::ptrdiff_t>(order.size());
    std::vector<T> ordered(order.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelSweep)
    for (std::ptrdiff_t k = 0; k < count; ++k) ordered[k] = array[order[k]];
    array.swap(ordered);
}

} // namespace slides
