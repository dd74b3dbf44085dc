#include "slides/integrate/size_distribution.h"

#include "slides/core/random.h"
#include "slides/integrate/csv_table.h"

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
    if (distribution.kind == RadiusDistributionKind::rosinRammler) tabulateRosinRammler();
    if (distribution.kind == RadiusDistributionKind::table) tabulateMeasured();
}

void RadiusSampler::tabulateRosinRammler() {
    // The table spans [minimum, maximum], an unbounded end where F is within 1e-17 of 0 or 1.
    const RadiusDistribution& distribution = distribution_;
    const double scale = distribution.scale, spread = distribution.spread;
    const double lower = std::max(distribution.minimum, scale * std::pow(1e-17, 1 / spread));
    const double upper = std::min(distribution.maximum, scale * std::pow(40.0, 1 / spread));
    const double first = std::log(lower), step = (std::log(upper) - first) / tableIntervals;
    within_ = Within::uniformInLogRadius;
    radius_.resize(tableIntervals + 1);
    cumulative_.assign(tableIntervals + 1, 0.0);
    const auto density = [&](double logRadius) {
        return rosinRammlerDensityPerLogRadius(std::exp(logRadius), distribution);
    };
    double previous = first;
    radius_[0] = lower;
    for (int i = 1; i <= tableIntervals; ++i) {
        const double next = first + i * step;
        radius_[i] = std::exp(next);
        cumulative_[i] =
            cumulative_[i - 1] + step / 6 *
                                     (density(previous) + 4 * density(0.5 * (previous + next)) +
                                      density(next)); // Simpson's rule
        previous = next;
    }
    for (double& fraction : cumulative_) fraction /= cumulative_.back();
}

void RadiusSampler::tabulateMeasured() {
    radius_ = distribution_.tableRadius;
    cumulative_.assign(radius_.size(), 0.0);
    const auto& given = distribution_.tableCumulative;
    const bool mass = distribution_.weighting == SizeWeighting::mass;
    within_ = mass ? Within::inverseCube : Within::uniformInRadius;
    for (std::size_t i = 1; i < radius_.size(); ++i) {
        const double a = radius_[i - 1], b = radius_[i], share = given[i] - given[i - 1];
        // Mass uniform in [a, b]: its number ∝ ∫ r⁻³ dr per unit mass.
        cumulative_[i] = cumulative_[i - 1] +
                         (mass ? share * (1 / (a * a) - 1 / (b * b)) / (2 * (b - a)) : share);
    }
    for (double& fraction : cumulative_) fraction /= cumulative_.back();
}

double RadiusSampler::fromTable(double u) const {
    const auto above = std::upper_bound(cumulative_.begin() + 1, cumulative_.end() - 1, u);
    const auto i = static_cast<std::size_t>(above - cumulative_.begin());
    const double share = (u - cumulative_[i - 1]) / (cumulative_[i] - cumulative_[i - 1]);
    const double a = radius_[i - 1], b = radius_[i];
    switch (within_) {
    case Within::uniformInLogRadius: return a * std::pow(b / a, share);
    case Within::uniformInRadius: return a + share * (b - a);
    case Within::inverseCube:
        return 1 / std::sqrt(1 / (a * a) - share * (1 / (a * a) - 1 / (b * b)));
    }
    return a;
}

double RadiusSampler::draw(std::uint64_t seed, std::uint64_t id) const {
    const RadiusDistribution& distribution = distribution_;
    if (distribution.kind == RadiusDistributionKind::fixed) return distribution.value;
    RandomStream random(seed, id, RandomPurpose::radius);
    if (distribution.kind == RadiusDistributionKind::table) return fromTable(random.uniform());
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
    if (radius_.empty()) return distribution_.meanRadius();
    double mean = 0;
    for (std::size_t i = 1; i < radius_.size(); ++i) {
        const double a = radius_[i - 1], b = radius_[i];
        // The interval's mean radius under its law: r⁻³ gives 2ab/(a + b), 1/r (uniform in
        // ln r) (b − a)/ln(b/a).
        const double within = within_ == Within::uniformInRadius ? 0.5 * (a + b)
                              : within_ == Within::inverseCube   ? 2 * a * b / (a + b)
                                                                 : (b - a) / std::log(b / a);
        mean += within * (cumulative_[i] - cumulative_[i - 1]);
    }
    return mean;
}

double drawRadius(const RadiusDistribution& distribution, std::uint64_t seed, std::uint64_t id) {
    return RadiusSampler(distribution).draw(seed, id);
}

void readSizeTable(const std::filesystem::path& file, RadiusDistribution& distribution) {
    const CsvTable table = readCsvTable(file, {"r", "d", "F"});
    const auto diameter = table.column("d"), radius = table.column("r");
    const auto fraction = table.column("F");
    if (diameter.has_value() == radius.has_value() || !fraction)
        table.fail(0, "F", "the header needs r (or d) and F, the cumulative fraction below");
    auto& radii = distribution.tableRadius;
    auto& cumulative = distribution.tableCumulative;
    for (std::size_t k = 0; k < table.rows.size(); ++k) {
        const double r = diameter ? 0.5 * table.rows[k][*diameter] : table.rows[k][*radius];
        const double F = table.rows[k][*fraction];
        if (!(r > 0)) table.fail(k, diameter ? "d" : "r", "must be a positive number");
        if (!radii.empty() && !(r > radii.back()))
            table.fail(k, diameter ? "d" : "r", "must increase from row to row");
        if (!(F >= 0 && F <= 1) || (!cumulative.empty() && F < cumulative.back()))
            table.fail(k, "F", "must rise from 0 to 1 (a cumulative fraction)");
        radii.push_back(r);
        cumulative.push_back(F);
    }
    if (cumulative.front() != 0 || cumulative.back() != 1)
        table.fail(cumulative.front() != 0 ? 0 : table.rows.size() - 1, "F",
                   "must be 0 on the first row and 1 on the last");
}

} // namespace slides
