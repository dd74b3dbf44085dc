#include "slides/integrate/packing_growth.h"

#include "slides/integrate/packing_grid.h"
#include "slides/integrate/packing_random_addition.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <vector>

namespace slides {

namespace {

constexpr double startFraction = 0.2;   ///< volume fraction of the random addition it starts from
constexpr double stepLength = 0.02;     ///< [R̄/v̄]
constexpr double stepTolerance = 1e-4;  ///< overlap / contact distance a step leaves
constexpr double finalTolerance = 1e-9; ///< overlap / contact distance at the end
constexpr double finalMargin = 1e-6;    ///< grown to (1 + margin) × the radii
constexpr int stepSweeps = 64;
constexpr int finalSweeps = 1000;
constexpr int finalRounds = 100;

struct Spheres {
    const PackingRegion& region;
    std::span<const double> radii;
    std::vector<Vec3> centre, velocity;
    PackingGrid grid;

    std::vector<std::pair<std::uint32_t, std::uint32_t>> pairs;

    /// Lists the pairs closer than their contact distance at scale s plus the skin [m].
    void listPairs(double scale, double skin) {
        grid.rebuild(centre);
        pairs.clear();
        for (std::size_t i = 0; i < centre.size(); ++i)
            grid.forEachNear(centre[i], [&](std::uint32_t j) {
                if (j <= i) return;
                const double reach = scale * (radii[i] + radii[j]) + skin;
                if (region.separation(centre[i], centre[j]).squaredNorm() < reach * reach)
                    pairs.emplace_back(static_cast<std::uint32_t>(i), j);
            });
    }

    /// Sweeps over the listed pairs at scale s until the largest overlap falls below tolerance
    /// (of the contact distance) or the sweeps run out; the largest overlap of the last sweep.
    double separate(double scale, double growthRate, double tolerance, int sweeps, long& count) {
        double worst = 0;
        for (int sweep = 0; sweep < sweeps; ++sweep) {
            ++count;
            worst = 0;
            for (const auto& [i, j] : pairs) worst = std::max(worst, push(i, j, scale, growthRate));
            if (worst < tolerance) break;
        }
        return worst;
    }

    /// Separates spheres i and j if they overlap and makes them recede from each other
    /// faster than their surfaces grow; the overlap / contact distance.
    double push(std::size_t i, std::size_t j, double scale, double growthRate) {
        const Vec3 d = region.separation(centre[i], centre[j]);
        const double contact = scale * (radii[i] + radii[j]);
        const double distanceSquared = d.squaredNorm();
        if (distanceSquared >= contact * contact) return 0;
        const double distance = std::sqrt(distanceSquared);
        const Vec3 normal = distance > 0 ? Vec3(d / distance) : Vec3::UnitX();
        const double massI = radii[i] * radii[i] * radii[i], massJ = radii[j] * radii[j] * radii[j];
        const double shareI = massJ / (massI + massJ), shareJ = massI / (massI + massJ);
        const double overlap = contact - distance;
        centre[i] += shareI * overlap * normal;
        centre[j] -= shareJ * overlap * normal;
        const double surfaceSpeed = growthRate * (radii[i] + radii[j]);
        const double receding = (velocity[i] - velocity[j]).dot(normal);
        if (receding < surfaceSpeed) {
            const double change = 2 * (surfaceSpeed - receding); // u_n' = 2γΣR − u_n
            velocity[i] += shareI * change * normal;
            velocity[j] -= shareJ * change * normal;
        }
        region.confine(centre[i], velocity[i], scale * radii[i]);
        region.confine(centre[j], velocity[j], scale * radii[j]);
        return overlap / contact;
    }
};

} // namespace

PackedEnsemble growLubachevskyStillinger(const PackingRegion& region, std::span<const double> radii,
                                         double growthRate, RandomStream& random) {
    if (radii.empty()) {
        PackedEnsemble none;
        none.complete = true;
        return none;
    }
    double volume = 0;
    for (double r : radii) volume += r * r * r;
    const double fullFraction = 4.0 / 3.0 * std::numbers::pi * volume / region.volume();
    double scale = std::cbrt(std::min(1.0, startFraction / fullFraction));
    std::vector<double> start(radii.begin(), radii.end());
    for (double& r : start) r *= scale;
    PackedEnsemble out = addRandomSequentially(region, start, random);
    if (!out.complete) return out;

    const double meanRadius =
        std::accumulate(radii.begin(), radii.end(), 0.0) / static_cast<double>(radii.size());
    const double largest = *std::max_element(radii.begin(), radii.end());
    const double skin = 0.1 * meanRadius; // far more than a step moves a sphere
    Spheres spheres{region,
                    radii,
                    std::move(out.centres),
                    {},
                    PackingGrid(region, 2 * (1 + finalMargin) * largest * 1.05),
                    {}};
    spheres.velocity.resize(radii.size());
    for (Vec3& v : spheres.velocity)
        v = meanRadius * Vec3(random.normal(), random.normal(), random.normal());
    const auto kineticEnergy = [&] {
        return std::accumulate(spheres.velocity.begin(), spheres.velocity.end(), 0.0,
                               [](double sum, const Vec3& v) { return sum + v.squaredNorm(); });
    };
    const double startEnergy = kineticEnergy();

    const double end = 1 + finalMargin;
    double rate = growthRate;
    out.complete = false;
    while (scale < end && rate >= 1e-3 * growthRate) {
        const std::vector<Vec3> before = spheres.centre, beforeVelocity = spheres.velocity;
        const double grown = std::min(end, scale + rate * stepLength);
        for (std::size_t i = 0; i < radii.size(); ++i) {
            spheres.centre[i] += spheres.velocity[i] * stepLength;
            region.confine(spheres.centre[i], spheres.velocity[i], grown * radii[i]);
        }
        spheres.listPairs(grown, skin);
        if (spheres.separate(grown, rate, stepTolerance, stepSweeps, out.sweeps) >= stepTolerance) {
            spheres.centre = before; // jamming: undo the step, grow slower
            spheres.velocity = beforeVelocity;
            rate *= 0.5;
            continue;
        }
        scale = grown;
        const double energy = kineticEnergy();
        if (energy > 0)
            for (Vec3& v : spheres.velocity) v *= std::sqrt(startEnergy / energy);
    }
    // Relax the last overlaps at rest, at the scale reached, listing the pairs anew now and
    // then (the spheres still shift), until a sweep over fresh pairs finds none.
    double worst = 1;
    for (int round = 0; round < finalRounds && worst >= finalTolerance; ++round) {
        spheres.listPairs(scale, skin);
        spheres.separate(scale, 0, finalTolerance, finalSweeps, out.sweeps);
        spheres.listPairs(scale, 0);
        worst = spheres.separate(scale, 0, 0, 1, out.sweeps);
    }
    out.complete = scale >= end && worst < finalTolerance;
    // Jammed short of the radii: scaled down until no two spheres overlap.
    const double finalScale = out.complete ? 1.0 : scale * (1 - 2 * worst) / (1 + finalMargin);
    out.centres = std::move(spheres.centre);
    out.radii.assign(radii.begin(), radii.end());
    for (double& r : out.radii) r *= finalScale;
    return out;
}

} // namespace slides
