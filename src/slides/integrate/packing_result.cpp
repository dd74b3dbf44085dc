#include "slides/integrate/packing_result.h"

#include <numbers>

namespace slides {

double PackedEnsemble::volumeFraction(double regionVolume) const {
    double volume = 0;
    for (std::size_t i = 0; i < centres.size(); ++i) volume += radii[i] * radii[i] * radii[i];
    return 4.0 / 3.0 * std::numbers::pi * volume / regionVolume;
}

} // namespace slides
