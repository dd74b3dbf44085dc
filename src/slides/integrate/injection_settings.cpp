#include "slides/integrate/injection_settings.h"

#include <cmath>

namespace slides {

double RadiusDistribution::meanRadius() const {
    switch (kind) {
    case RadiusDistributionKind::fixed: return value;
    case RadiusDistributionKind::normal: return mean;
    case RadiusDistributionKind::logNormal: {
        const double sigma = std::log(geometricStandardDeviation);
        return median * std::exp(0.5 * sigma * sigma);
    }
    }
    return value;
}

} // namespace slides
