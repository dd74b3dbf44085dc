#include "slides/collide/coulomb_forces.h"

#include "slides/core/parallel.h"
#include "slides/physics/contact_pair.h"

#include <algorithm>
#include <optional>

namespace slides {

CoulombForces::CoulombForces(const CoulombSettings& settings, double particleDensity,
                             const Box& domain)
    : settings_(settings), particleDensity_(particleDensity), domain_(domain) {}

bool CoulombForces::isCurrent(const ParticleCloud& cloud) const {
    return cloud.id == evaluatedIds_ && cloud.position == evaluatedPositions_;
}

void CoulombForces::evaluate(const ParticleCloud& cloud) {
    if (isCurrent(cloud)) return;
    const std::size_t count = cloud.size();
    // Cells of the cut-off's edge: every pair closer than it is offered once. A particle that
    // has left the domain (however far, or to a state that is not finite) feels and exerts
    // nothing: it escapes at the step's end, where a state that is not finite stops the run.
    grid_.build(cloud.position, settings_.cutoff, domain_);
    const double reach = settings_.cutoff * settings_.cutoff;
    pairs_ =
        collectPairs<Pair>(grid_, [&](std::uint32_t s, std::uint32_t t) -> std::optional<Pair> {
            const Vec3 separation = grid_.positionAt(s) - grid_.positionAt(t);
            if (!(separation.squaredNorm() < reach)) return std::nullopt;
            const std::uint32_t a = grid_.pointAt(s), b = grid_.pointAt(t);
            if (cloud.charge[a] == 0 || cloud.charge[b] == 0) return std::nullopt;
            const CoulombPair pair = coulombPair(settings_, cloud.charge[a], cloud.charge[b],
                                                 cloud.radius[a], cloud.radius[b]);
            return Pair{a, b, pair.forceOn(separation), pair.energy(separation.norm())};
        });

    // Each particle's pairs, ordered by partner id (indexed as 2 p + side).
    pairStart_.assign(count + 1, 0);
    for (const Pair& pair : pairs_) {
        ++pairStart_[pair.first + 1];
        ++pairStart_[pair.second + 1];
    }
    for (std::size_t i = 0; i < count; ++i) pairStart_[i + 1] += pairStart_[i];
    pairOf_.resize(pairStart_[count]);
    std::vector<std::uint32_t> next(pairStart_.begin(), pairStart_.end() - 1);
    for (std::uint32_t p = 0; p < pairs_.size(); ++p) {
        pairOf_[next[pairs_[p].first]++] = 2 * p;
        pairOf_[next[pairs_[p].second]++] = 2 * p + 1;
    }
    const auto partnerId = [&](std::uint32_t slot) {
        const Pair& pair = pairs_[slot / 2];
        return cloud.id[slot % 2 == 1 ? pair.first : pair.second];
    };
    forces_.assign(count, Vec3::Zero());
    const auto particles = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static) if (particles >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < particles; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const auto begin = pairOf_.begin() + pairStart_[i],
                   end = pairOf_.begin() + pairStart_[i + 1];
        std::sort(begin, end,
                  [&](std::uint32_t x, std::uint32_t y) { return partnerId(x) < partnerId(y); });
        Vec3 force = Vec3::Zero();
        for (auto slot = begin; slot != end; ++slot) {
            const Vec3& onFirst = pairs_[*slot / 2].force;
            force += *slot % 2 == 0 ? onFirst : Vec3(-onFirst);
        }
        forces_[i] = force;
    }
    evaluatedIds_ = cloud.id;
    evaluatedPositions_ = cloud.position;
}

double CoulombForces::potentialEnergy() const {
    double energy = 0;
    for (const Pair& pair : pairs_) energy += pair.energy;
    return energy;
}

void CoulombForces::halfKick(ParticleCloud& cloud, const std::vector<double>& stepLengths,
                             std::span<const double> densities) const {
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        // A particle without force keeps its velocity as it is (a zero kick could turn −0 to +0).
        if (forces_[i].isZero(0)) continue;
        const double density = densities.empty() ? particleDensity_ : densities[i];
        cloud.velocity[i] +=
            forces_[i] * (0.5 * stepLengths[i] / sphereMass(cloud.radius[i], density));
    }
}

} // namespace slides
