#include "slides/integrate/ensemble.h"

#include "slides/core/random.h"
#include "slides/integrate/packing_growth.h"
#include "slides/integrate/packing_random_addition.h"

namespace slides {

PackedEnsemble packEnsemble(const EnsembleSettings& settings, std::span<const double> radii,
                            std::uint64_t seed, std::uint64_t id) {
    RandomStream random(seed, id, RandomPurpose::injection, 0x50414b); // "PAK": not an attempt
    switch (settings.method) {
    case PackingMethod::randomSequentialAddition:
        return addRandomSequentially(settings.region, radii, random);
    case PackingMethod::lubachevskyStillinger:
        return growLubachevskyStillinger(settings.region, radii, settings.growthRate, random);
    }
    return {};
}

} // namespace slides
