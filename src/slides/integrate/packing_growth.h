// Lubachevsky–Stillinger growth (Lubachevsky & Stillinger 1990, J. Stat. Phys. 60, 561; with the
// growth rate proportional to each sphere's radius, Kansal, Torquato & Stillinger 2002): dense
// random packings. The spheres start from a random sequential addition at a fraction of their
// radii, move with random velocities and grow, dR_i/dt = γ R_i (Eq. 4.32), colliding
// elastically, until they reach their full radii.
//
// Reference: Section 4.3, Algorithm 3 (time-stepped, as the reference implements it, rather
// than event-driven). Time is in units of R̄/v̄ (mean radius over rms speed component); a step
// of 0.02 moves a sphere about 3 % of its radius. Each step: move, grow, list the pairs within
// their contact distance plus a skin of 0.1 R̄ (integrate/packing_grid.h), then sweeps over them
// push overlapping spheres apart along their line of centres, in inverse proportion to their
// masses (∝ R³), and reverse their normal velocity relative to the growing surfaces
// (u_n' = 2γ(R_i + R_j) − u_n, Eq. 4.30–4.31 with the growth as the added speed), until no
// overlap exceeds 1e-4 of a contact distance; then the speeds are rescaled to their start (the
// energy the collisions add, removed as Lubachevsky & Stillinger do). A step whose overlaps do
// not relax in 64 sweeps is undone and γ halved; below γ/1000 the packing is jammed and stops
// short of its radii. It ends grown to 1 + 1e-6 of the radii with overlaps below 1e-9 of a
// contact distance: at the full radii no two spheres overlap.
//
//     ensembleCoeffs { method lubachevskyStillinger; growthRate 0.2; shape box; ... }
#pragma once

#include "slides/core/random.h"
#include "slides/integrate/packing_region.h"
#include "slides/integrate/packing_result.h"

#include <span>

namespace slides {

/// Packs spheres of the radii into the region by growth at rate γ (growthRate, per unit time
/// R̄/v̄); complete unless jammed first (then the radii are the largest reached, all scaled
/// alike).
PackedEnsemble growLubachevskyStillinger(const PackingRegion& region, std::span<const double> radii,
                                         double growthRate, RandomStream& random);

} // namespace slides
