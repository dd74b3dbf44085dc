// Random sequential addition (Widom 1966; Fig. 4.1 of the reference): spheres are placed one
// after another at uniformly random points, an attempt that overlaps a placed sphere or a wall
// is discarded, a placed sphere never moves.
//
// Reference: Section 4.3, Fig. 4.1. Each attempt reads the 27 cells of integrate/packing_grid.h
// around its point: O(1). Uniform attempts find the last gaps ever more rarely (the coverage
// approaches saturation as t^(−1/3), Pomeau 1980), so once 4096 attempts for one sphere fail,
// attempts are drawn from the voxels not yet known to be covered (Zhang & Torquato 2013, Phys.
// Rev. E 88, 053312): a voxel is dropped once its farthest point lies within the exclusion
// sphere (r_j + r_min) of a placed sphere j, the survivors are halved in edge after as many
// attempts as there are voxels, and an empty list proves the packing saturated (a list that
// outgrows 2^21 voxels, or 30 halvings, ends the search as stalled). For equal
// spheres saturation is φ_s = 0.38413 in 3-D (Zhang & Torquato 2013). Random numbers come from
// one stream, so a packing depends on the seed only.
//
//     ensembleCoeffs { method randomSequentialAddition; shape box; min (0 0 0); max (1 1 1); }
#pragma once

#include "slides/core/random.h"
#include "slides/integrate/packing_region.h"
#include "slides/integrate/packing_result.h"

#include <span>

namespace slides {

/// Places spheres of the radii in order until one finds no room; when every later attempt must
/// fail the result is saturated.
PackedEnsemble addRandomSequentially(const PackingRegion& region, std::span<const double> radii,
                                     RandomStream& random);

} // namespace slides
