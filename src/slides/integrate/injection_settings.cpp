#include "slides/integrate/injection_settings.h"

#include "slides/integrate/size_distribution.h"

#include <algorithm>
#include <cmath>

namespace slides {

double RadiusDistribution::meanRadius() const {
    switch (kind) {
    case RadiusDistributionKind::fixed: return value;
    case RadiusDistributionKind::normal: return mean;
    case RadiusDistributionKind::logNormal: {
        const double sigma = std::log(geometricStandardDeviation);
        const double numberMedian =
            weighting == SizeWeighting::mass ? median * std::exp(-3 * sigma * sigma) : median;
        return numberMedian * std::exp(0.5 * sigma * sigma);
    }
    case RadiusDistributionKind::rosinRammler:
    case RadiusDistributionKind::table: return RadiusSampler(*this).meanRadius();
    }
    return value;
}

std::int32_t injectorOfId(const std::vector<std::uint64_t>& firstIds, std::uint64_t id) {
    const auto after = std::upper_bound(firstIds.begin(), firstIds.end(), id);
    return static_cast<std::int32_t>(std::max<std::ptrdiff_t>(after - firstIds.begin() - 1, 0));
}

InjectorSettings singleInjector(const InjectionSettings& injection, const JetNozzle& nozzle,
                                const ParticleSettings& particles) {
    InjectorSettings injector;
    injector.name = "nozzle";
    injector.nozzle = nozzle;
    injector.injection = injection;
    injector.count = particles.count;
    injector.radius = particles.radius;
    return injector;
}

} // namespace slides
