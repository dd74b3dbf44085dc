// Packed ensembles: an injector (`model ensemble`) whose particles start at rest, all at its
// start time, from a packing of their radii (drawn from its radius distribution, id by id) in a
// box or a cylinder: random sequential addition (integrate/packing_random_addition.h) up to its
// saturation, φ ≈ 0.38 for equal spheres, or Lubachevsky–Stillinger growth
// (integrate/packing_growth.h) for dense packings up to jamming, φ ≈ 0.63.
//
// Reference: Section 4.3, Fig. 4.1, Eq. 4.30–4.32, Algorithm 3. The packing is made once, on
// reading the case, from the stream (seed, first id): the same on every rank, at every thread
// count and on restart.
//
//     injectors
//     {
//         bed { model ensemble; count 2000;
//               radiusDistribution { type normal; mean 50e-6; standardDeviation 5e-6;
//                                    minimum 30e-6; maximum 70e-6; }
//               ensembleCoeffs { method lubachevskyStillinger; growthRate 0.2; shape box;
//                                min (0 0 0); max (1.5e-3 1.5e-3 1.5e-3); periodic no; } }
//         column { model ensemble; count 500; centre (0 0 0); axis (0 0 1); radius 1e-3;
//                  ensembleCoeffs { method randomSequentialAddition; shape cylinder;
//                                   length 2e-3; } }
//     }
//
// How to add a method: an enumerator, its name in packingMethodNames() and its case in
// packEnsemble (integrate/ensemble.cpp).
#pragma once

#include "slides/integrate/packing_region.h"
#include "slides/integrate/packing_result.h"

#include <array>
#include <cstdint>
#include <span>
#include <string_view>

namespace slides {

enum class PackingMethod { randomSequentialAddition, lubachevskyStillinger };

struct PackingMethodName {
    PackingMethod value;
    std::string_view name;
};

constexpr std::array<PackingMethodName, 2> packingMethodNames() {
    return {{{PackingMethod::randomSequentialAddition, "randomSequentialAddition"},
             {PackingMethod::lubachevskyStillinger, "lubachevskyStillinger"}}};
}

struct EnsembleSettings {
    PackingMethod method = PackingMethod::randomSequentialAddition;
    PackingRegion region;
    double growthRate = 0.2; ///< lubachevskyStillinger: γ of dR/dt = γR, per unit time R̄/v̄
};

/// Packs spheres of the radii (in order) by the settings' method, from the stream (seed, id).
PackedEnsemble packEnsemble(const EnsembleSettings& settings, std::span<const double> radii,
                            std::uint64_t seed, std::uint64_t id);

} // namespace slides
