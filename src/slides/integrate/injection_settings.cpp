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

std::int32_t InjectorIds::injectorOf(std::uint64_t id) const {
    if (id >= total && !firstIds.empty())
        return static_cast<std::int32_t>((id - total) % firstIds.size());
    const auto after = std::upper_bound(firstIds.begin(), firstIds.end(), id);
    return static_cast<std::int32_t>(std::max<std::ptrdiff_t>(after - firstIds.begin() - 1, 0));
}

InjectorIds injectorIdsOf(const std::vector<InjectorSettings>& injectors) {
    InjectorIds ids;
    for (const InjectorSettings& injector : injectors) {
        ids.firstIds.push_back(injector.firstId);
        ids.total = injector.firstId + static_cast<std::uint64_t>(injector.count);
    }
    return ids;
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
