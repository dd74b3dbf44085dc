#include "slides/integrate/injector.h"

#include "slides/core/random.h"

#include <cmath>
#include <numbers>

namespace slides {

double drawRadius(const RadiusDistribution& distribution, std::uint64_t seed, ParticleId id) {
    if (distribution.kind == RadiusDistributionKind::fixed) return distribution.value;
    RandomStream random(seed, id, RandomPurpose::radius);
    const double sigma = std::log(distribution.geometricStandardDeviation);
    // The reader guarantees the mean lies inside [minimum, maximum], so redraws terminate.
    while (true) {
        const double deviate = random.normal();
        const double radius = distribution.kind == RadiusDistributionKind::normal
                                  ? distribution.mean + distribution.standardDeviation * deviate
                                  : distribution.median * std::exp(sigma * deviate);
        if (radius > distribution.minimum && radius < distribution.maximum && radius > 0)
            return radius;
    }
}

Vec3 latticeSite(const InjectionSettings& injection, ParticleId id) {
    const auto& sites = injection.latticeSites;
    const auto nx = static_cast<ParticleId>(sites[0]), ny = static_cast<ParticleId>(sites[1]);
    const Vec3 cell(static_cast<double>(id % nx), static_cast<double>(id / nx % ny),
                    static_cast<double>(id / (nx * ny)));
    return injection.latticeOrigin + injection.latticeSpacing * (cell.array() + 0.5).matrix();
}

Injector::Injector(const InjectionSettings& injection, const JetNozzle& nozzle,
                   const ParticleSettings& particles)
    : injection_(injection), nozzle_(nozzle), count_(particles.count), radius_(particles.radius) {}

double Injector::injectionTime(ParticleId id) const {
    return injection_.mode == InjectionMode::rate ? static_cast<double>(id) / injection_.rate : 0.0;
}

void Injector::injectUntil(double until, double time, const CarrierField& carrier,
                           ParticleCloud& cloud) {
    const long first = injected_;
    long last = first;
    while (last < count_ && injectionTime(static_cast<ParticleId>(last)) < until) ++last;
    if (last == first) return;

    const JetNozzle& nozzle = nozzle_;
    const Vec3 across = nozzle.crossSpanDirection;
    const Vec3 other = nozzle.axis.cross(across);
    const auto count = static_cast<std::size_t>(last - first);
    positions_.resize(count);
    randomVelocities_.resize(count);
    for (std::size_t k = 0; k < count; ++k) {
        const auto id = static_cast<ParticleId>(first) + k;
        RandomStream random(injection_.seed, id, RandomPurpose::injection);
        if (injection_.mode == InjectionMode::lattice) {
            positions_[k] = latticeSite(injection_, id);
            const double spread = injection_.latticeVelocitySpread;
            for (int axis = 0; axis < 3; ++axis)
                randomVelocities_[k][axis] = spread * (2 * random.uniform() - 1);
            continue;
        }
        const double radialFraction = std::sqrt(random.uniform()); // uniform in disc area
        const double angle = 2.0 * std::numbers::pi * random.uniform();
        const double direction = 2.0 * std::numbers::pi * random.uniform();
        positions_[k] = nozzle.centre + nozzle.radius * radialFraction *
                                            (std::cos(angle) * across + std::sin(angle) * other);
        randomVelocities_[k] = injection_.crossSpanSpeed *
                               (std::cos(direction) * across + std::sin(direction) * other);
    }
    // A mesh carrier's search finds each particle's cell: the cloud keeps it, so the first
    // step walks from there instead of searching again.
    const bool keepsLocations = carrier.keepsLocations();
    if (keepsLocations) {
        cloud.carrierLocation.resize(cloud.size(), -1);
        cloud.carrierLocation.resize(cloud.size() + count, -1);
        carrier.sampleFrom(positions_,
                           std::span(cloud.carrierLocation).subspan(cloud.size(), count), time,
                           CarrierNeeds{}, gas_);
    } else {
        carrier.sample(positions_, time, CarrierNeeds{}, gas_);
    }
    for (std::size_t k = 0; k < count; ++k) {
        const auto id = static_cast<ParticleId>(first) + k;
        cloud.add(id, positions_[k], gas_.velocity[k] + randomVelocities_[k],
                  drawRadius(radius_, injection_.seed, id));
    }
    injected_ = last;
}

} // namespace slides
