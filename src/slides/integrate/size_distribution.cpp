#include "slides/integrate/size_distribution.h"

#include "slides/core/random.h"

#include <algorithm>
#include <cmath>

namespace slides {

namespace {

constexpr int tableIntervals = 4096;

/// e^(−(r/r̄)^n), the fraction above r.
double rosinRammlerSurvival(double radius, double scale, double spread) {
    return std::exp(-std::pow(radius / scale, spread));
}

/// Number (or mass) density per unit ln r of the untruncated Rosin–Rammler distribution.
double rosinRammlerDensityPerLogRadius(double radius, const RadiusDistribution& distribution) {
    const double x = std::pow(radius / distribution.scale, distribution.spread);
    const double massDensity = distribution.spread * x * std::exp(-x); // f_m(r) · r
    return distribution.weighting == SizeWeighting::mass ? massDensity / std::pow(radius, 3)
                                                         : massDensity;
}

} // namespace

double rosinRammlerCumulative(double radius, double scale, double spread) {
    return -std::expm1(-std::pow(radius / scale, spread));
}

RadiusSampler::RadiusSampler(const RadiusDistribution& distribution) : distribution_(distribution) {
    if (distribution.kind != RadiusDistributionKind::rosinRammler) return;
    // The table spans [minimum, maximum], an unbounded end where F is within 1e-17 of 0 or 1.
    const double scale = distribution.scale, spread = distribution.spread;
    const double lower = std::max(distribution.minimum, scale * std::pow(1e-17, 1 / spread));
    const double upper = std::min(distribution.maximum, scale * std::pow(40.0, 1 / spread));
    const double first = std::log(lower), step = (std::log(upper) - first) / tableIntervals;
    logRadius_.resize(tableIntervals + 1);
    cumulative_.assign(tableIntervals + 1, 0.0);
    const auto density = [&](double logRadius) {
        return rosinRammlerDensityPerLogRadius(std::exp(logRadius), distribution);
    };
    for (int i = 0; i <= tableIntervals; ++i) {
        logRadius_[i] = first + i * step;
        if (i == 0) continue;
        const double a = logRadius_[i - 1], b = logRadius_[i];
        cumulative_[i] =
            cumulative_[i - 1] +
            step / 6 * (density(a) + 4 * density(0.5 * (a + b)) + density(b)); // Simpson's rule
    }
    const double total = cumulative_.back();
    for (double& fraction : cumulative_) fraction /= total;
}

double RadiusSampler::fromTable(double u) const {
    const auto above = std::upper_bound(cumulative_.begin() + 1, cumulative_.end() - 1, u);
    const auto i = static_cast<std::size_t>(above - cumulative_.begin());
    const double share = (u - cumulative_[i - 1]) / (cumulative_[i] - cumulative_[i - 1]);
    return std::exp(logRadius_[i - 1] + share * (logRadius_[i] - logRadius_[i - 1]));
}

double RadiusSampler::draw(std::uint64_t seed, std::uint64_t id) const {
    const RadiusDistribution& distribution = distribution_;
    if (distribution.kind == RadiusDistributionKind::fixed) return distribution.value;
    RandomStream random(seed, id, RandomPurpose::radius);
    if (distribution.kind == RadiusDistributionKind::rosinRammler) {
        const double u = random.uniform();
        if (distribution.weighting == SizeWeighting::mass) return fromTable(u);
        // The truncated distribution inverted in closed form, through the survival fraction.
        const double scale = distribution.scale, spread = distribution.spread;
        const double above = rosinRammlerSurvival(distribution.minimum, scale, spread);
        const double beyond = std::isfinite(distribution.maximum)
                                  ? rosinRammlerSurvival(distribution.maximum, scale, spread)
                                  : 0.0;
        return scale * std::pow(-std::log(above - u * (above - beyond)), 1 / spread);
    }
    const double sigma = std::log(distribution.geometricStandardDeviation);
    // A mass-weighted logNormal is the number logNormal of median r_m e^(−3σ²) (Hatch–Choate).
    const double median = distribution.weighting == SizeWeighting::mass
                              ? distribution.median * std::exp(-3 * sigma * sigma)
                              : distribution.median;
    // The reader guarantees the mean lies inside [minimum, maximum], so redraws terminate.
    while (true) {
        const double deviate = random.normal();
        const double radius = distribution.kind == RadiusDistributionKind::normal
                                  ? distribution.mean + distribution.standardDeviation * deviate
                                  : median * std::exp(sigma * deviate);
        if (radius > distribution.minimum && radius < distribution.maximum && radius > 0)
            return radius;
    }
}

double RadiusSampler::meanRadius() const {
    if (distribution_.kind != RadiusDistributionKind::rosinRammler)
        return distribution_.meanRadius();
    double mean = 0;
    for (std::size_t i = 1; i < logRadius_.size(); ++i)
        mean += std::exp(0.5 * (logRadius_[i - 1] + logRadius_[i])) *
                (cumulative_[i] - cumulative_[i - 1]);
    return mean;
}

double drawRadius(const RadiusDistribution& distribution, std::uint64_t seed, std::uint64_t id) {
    return RadiusSampler(distribution).draw(seed, id);
}

} // namespace slides
