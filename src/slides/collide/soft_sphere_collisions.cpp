#include "slides/collide/soft_sphere_collisions.h"

#include "slides/collide/soft_sphere_pair.h"
#include "slides/core/parallel.h"
#include "slides/physics/contact_pair.h"

#include <algorithm>
#include <optional>
#include <tuple>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace slides {

namespace {

bool byIds(const ContactSpring& x, const ContactSpring& y) {
    return std::tie(x.first, x.second) < std::tie(y.first, y.second);
}

double inertiaPerMass(double radius) { return 0.4 * radius * radius; } // solid sphere, I/m

} // namespace

SoftSphereCollisions::SoftSphereCollisions(const CollisionSettings& collisions,
                                           const ParticleSettings& particles,
                                           const std::vector<Surface>& surfaces, const Box& domain)
    : settings_(collisions), particles_(particles), surfaces_(surfaces), domain_(domain),
      newWallContacts_(surfaces.size(), 0) {
    law_ = softContactLawOf(collisions);
    // The moduli do not depend on the bodies' sizes: one unit sphere stands for every particle
    // of a species; two species' pair takes both materials (Hertz's E*, G*).
    const std::vector<ParticleSpecies> species = particles.allSpecies();
    speciesCount_ = species.size();
    for (const ParticleSpecies& a : species)
        for (const ParticleSpecies& b : species)
            particleModuli_.push_back(
                contactPair({1.0, 1.0, &a.material}, ContactBody{1.0, 1.0, &b.material}));
    for (const ParticleSpecies& a : species)
        for (std::size_t s = 0; s < surfaces.size(); ++s)
            wallModuli_.push_back(contactPair({1.0, 1.0, &a.material},
                                              ContactBody{.material = &surfaces[s].material}));
    for (std::size_t s = 0; s < surfaces.size(); ++s)
        if (meetsBySoftContact(collisions, surfaces[s].interaction)) softWalls_.push_back(s);
}

void SoftSphereCollisions::halfKick(ParticleCloud& cloud,
                                    const std::vector<double>& stepLengths) const {
    const auto kick = [&](std::size_t i) {
        // A particle without load keeps its velocity as it is (a zero kick could turn −0 to +0).
        const Vec3& force = cloud.contactForce[i];
        const Vec3& torque = cloud.contactTorque[i];
        if (force.isZero(0) && torque.isZero(0)) return;
        const double mass = sphereMass(cloud.radius[i], particles_.densityOf(cloud.id[i]));
        const double kickPerForce = 0.5 * stepLengths[i] / mass;
        cloud.velocity[i] += force * kickPerForce;
        cloud.angularVelocity[i] += torque * (kickPerForce / inertiaPerMass(cloud.radius[i]));
    };
    if (loadedInPlace(cloud)) {
        const auto count = static_cast<std::ptrdiff_t>(loaded_.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
        for (std::ptrdiff_t k = 0; k < count; ++k) kick(loaded_[k]);
        return;
    }
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i) kick(static_cast<std::size_t>(i));
}

bool SoftSphereCollisions::loadedInPlace(const ParticleCloud& cloud) const {
    if (!loadsListed_ || cloud.contactForce.size() != cloud.size()) return false;
    const auto count = static_cast<std::ptrdiff_t>(loaded_.size());
    bool moved = false;
#pragma omp parallel for schedule(static) reduction(|| : moved) if (count >= minimumParallelSweep)
    for (std::ptrdiff_t k = 0; k < count; ++k)
        moved = moved || loaded_[k] >= cloud.size() || cloud.id[loaded_[k]] != loadedIds_[k];
    return !moved;
}

bool SoftSphereCollisions::listIsStale(const ParticleCloud& cloud) const {
    if (builtIds_.size() != cloud.size()) return true;
    // No pair left out of the list can touch while no particle has moved half the skin.
    const double limit = 0.25 * skin_ * skin_;
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
    bool stale = false;
#pragma omp parallel for schedule(static) reduction(|| : stale) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i)
        stale = stale || builtIds_[i] != cloud.id[i] ||
                (cloud.position[i] - builtPositions_[i]).squaredNorm() > limit;
    return stale;
}

ContactPair SoftSphereCollisions::pairOf(const Entry& entry, const ParticleCloud& cloud) const {
    const double radius = cloud.radius[entry.first];
    const ParticleId id = cloud.id[entry.first];
    const auto species = static_cast<std::size_t>(particles_.speciesOf(id));
    const double density = particles_.densityOf(id);
    ContactPair pair;
    if (entry.second >= 0) {
        const auto second = static_cast<std::size_t>(entry.second);
        const double other = cloud.radius[second];
        const ParticleId otherId = cloud.id[second];
        const auto otherSpecies = static_cast<std::size_t>(particles_.speciesOf(otherId));
        pair = particleModuli_[speciesCount_ * species + otherSpecies];
        pair.radius = harmonicSum(radius, other);
        pair.mass = harmonicSum(sphereMass(radius, density),
                                sphereMass(other, particles_.densityOf(otherId)));
    } else {
        pair =
            wallModuli_[surfaces_.size() * species + static_cast<std::size_t>(-1 - entry.second)];
        pair.radius = radius; // a plane: infinite radius and mass
        pair.mass = sphereMass(radius, density);
    }
    return pair;
}

void SoftSphereCollisions::buildList(const ParticleCloud& cloud) {
    std::vector<ContactSpring> handed = springs();
    handed.insert(handed.end(), pendingSprings_.begin(), pendingSprings_.end());
    std::sort(handed.begin(), handed.end(), byIds);
    pendingSprings_.clear();

    double cellSize = 0;
    std::tie(skin_, cellSize) = skinAndCellSize(cloud);
    // A particle that has left the domain (however far, or to a state that is not finite)
    // touches nothing: it escapes at the step's end.
    grid_.build(cloud.position, cellSize, domain_);
    // The search reads positions and radii in the grid's cell order, from memory in order.
    slotRadius_.resize(grid_.size());
    for (std::size_t slot = 0; slot < grid_.size(); ++slot)
        slotRadius_[slot] = cloud.radius[grid_.pointAt(slot)];
    // The pairs, and the walls each particle comes within reach of, in the grid's cell order.
    entries_ = collectPairsAndSingles<Entry>(
        grid_,
        [&](std::uint32_t s, std::uint32_t t) {
            const double reach = slotRadius_[s] + slotRadius_[t] + skin_;
            if ((grid_.positionAt(s) - grid_.positionAt(t)).squaredNorm() >= reach * reach)
                return std::optional<Entry>();
            std::uint32_t a = grid_.pointAt(s), b = grid_.pointAt(t);
            if (cloud.id[a] > cloud.id[b]) std::swap(a, b);
            return std::optional<Entry>({a, static_cast<std::int32_t>(b), {}, false});
        },
        [&](std::uint32_t slot, std::vector<Entry>& found) {
            for (const std::size_t s : softWalls_) {
                const Surface& wall = surfaces_[s];
                if ((grid_.positionAt(slot) - wall.point).dot(wall.normal) <
                    slotRadius_[slot] + skin_)
                    found.push_back(
                        {grid_.pointAt(slot), -1 - static_cast<std::int32_t>(s), {}, false});
            }
        });

    // Touching contacts keep their springs through the rebuild.
    copyInParallel(cloud.id, builtIds_);
    copyInParallel(cloud.position, builtPositions_);
    const auto entryCount = static_cast<std::ptrdiff_t>(entries_.size());
#pragma omp parallel for schedule(static) if (entryCount >= minimumParallelBatch)
    for (std::ptrdiff_t e = 0; e < entryCount; ++e) {
        Entry& entry = entries_[static_cast<std::size_t>(e)];
        const ContactSpring key = springOf(entry);
        const auto found = std::lower_bound(handed.begin(), handed.end(), key, byIds);
        if (found != handed.end() && !byIds(key, *found)) {
            entry.spring.displacement = found->displacement;
            entry.spring.largestOverlap = found->largestOverlap;
            entry.touching = true;
        }
    }
    indexEntriesByParticle();
    ++listBuilds_;
}

std::pair<double, double> SoftSphereCollisions::skinAndCellSize(const ParticleCloud& cloud) const {
    const double largestRadius =
        cloud.empty() ? 0 : *std::max_element(cloud.radius.begin(), cloud.radius.end());
    const double skin = settings_.softSphere.neighbourSkin * largestRadius;
    return {skin, 2 * largestRadius + skin};
}

std::vector<std::uint32_t> SoftSphereCollisions::cellOrder(const ParticleCloud& cloud) {
    grid_.build(cloud.position, skinAndCellSize(cloud).second, domain_);
    std::vector<std::uint32_t> order(grid_.size());
    std::vector<std::uint8_t> placed(cloud.size(), 0);
    for (std::size_t slot = 0; slot < grid_.size(); ++slot) {
        order[slot] = grid_.pointAt(slot);
        placed[order[slot]] = 1;
    }
    for (std::uint32_t i = 0; i < cloud.size(); ++i)
        if (!placed[i]) order.push_back(i);
    return order;
}

void SoftSphereCollisions::indexEntriesByParticle() {
    const std::size_t count = builtIds_.size();
    entryStart_.assign(count + 1, 0);
    for (const Entry& entry : entries_) {
        ++entryStart_[entry.first + 1];
        if (entry.second >= 0) ++entryStart_[static_cast<std::size_t>(entry.second) + 1];
    }
    for (std::size_t i = 0; i < count; ++i) entryStart_[i + 1] += entryStart_[i];
    entryOf_.resize(entryStart_[count]);
    std::vector<std::uint32_t> next(entryStart_.begin(), entryStart_.end() - 1);
    for (std::uint32_t e = 0; e < entries_.size(); ++e) {
        entryOf_[next[entries_[e].first]++] = 2 * e;
        if (entries_[e].second >= 0)
            entryOf_[next[static_cast<std::size_t>(entries_[e].second)]++] = 2 * e + 1;
    }
    const auto partnerId = [&](std::uint32_t slot) {
        const ContactSpring ids = springOf(entries_[slot / 2]);
        return slot % 2 == 1 ? ids.first : ids.second;
    };
    const auto particles = static_cast<std::ptrdiff_t>(count);
#pragma omp parallel for schedule(static) if (particles >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < particles; ++i)
        std::sort(entryOf_.begin() + entryStart_[i], entryOf_.begin() + entryStart_[i + 1],
                  [&](std::uint32_t x, std::uint32_t y) { return partnerId(x) < partnerId(y); });
}

void SoftSphereCollisions::updateLoads(ParticleCloud& cloud, double dt) {
    if (listIsStale(cloud)) buildList(cloud);
    const auto sphere = [&](std::size_t i) -> ContactSphere {
        return {cloud.position[i], cloud.velocity[i], cloud.angularVelocity[i], cloud.radius[i]};
    };
    // Most entries are apart, which a squared distance tells before any root is taken.
    const auto apart = [&](const Entry& entry) {
        const std::size_t a = entry.first;
        if (entry.second >= 0) {
            const auto b = static_cast<std::size_t>(entry.second);
            const double reach = cloud.radius[a] + cloud.radius[b];
            return (cloud.position[a] - cloud.position[b]).squaredNorm() >= reach * reach;
        }
        const Surface& wall = surfaces_[static_cast<std::size_t>(-1 - entry.second)];
        return (cloud.position[a] - wall.point).dot(wall.normal) >= cloud.radius[a];
    };
    std::fill(newWallContacts_.begin(), newWallContacts_.end(), 0);
    loads_.resize(entries_.size());
    const bool conducts =
        settings_.conduction.model != ContactConduction::none && !cloud.temperature.empty();
    long begun = 0;
    // The loaded entries, ascending.
    loadedEntries_ = collectInOrder<std::uint32_t>(
        static_cast<std::ptrdiff_t>(entries_.size()),
        [&](std::ptrdiff_t e, std::vector<std::uint32_t>& loaded) {
            Entry& entry = entries_[static_cast<std::size_t>(e)];
            // A contact that parted in this step takes the load of its parting once, if its law
            // has one (partingNormalForce); the pair functions reset its spring.
            const bool mayPart = entry.touching && mayPull(law_);
            if (apart(entry) && !mayPart) {
                if (entry.touching || entry.parting)
                    entry = {entry.first, entry.second, {}, false, false};
                return;
            }
            ContactLoad& load = loads_[static_cast<std::size_t>(e)];
            const ContactPair pair = pairOf(entry, cloud);
            if (entry.second >= 0) {
                load = sphereSphereLoad(pair, law_, sphere(entry.first),
                                        sphere(static_cast<std::size_t>(entry.second)),
                                        entry.spring, dt);
            } else {
                const Surface& wall = surfaces_[static_cast<std::size_t>(-1 - entry.second)];
                load = sphereWallLoad(pair, law_, sphere(entry.first), wall.point, wall.normal,
                                      entry.spring, dt);
            }
            const bool touching = load.overlap > 0;
            if (touching && conducts && entry.second >= 0) // Eq. 2.118
                load.conductedPower = contactConductance(settings_.conduction, pair.radius) *
                                      (cloud.temperature[static_cast<std::size_t>(entry.second)] -
                                       cloud.temperature[entry.first]);
            if (touching && !entry.touching) {
                if (entry.second >= 0) {
#pragma omp atomic
                    ++begun;
                } else {
#pragma omp atomic
                    ++newWallContacts_[static_cast<std::size_t>(-1 - entry.second)];
                }
            }
            entry.touching = touching;
            entry.parting = !touching && mayPart;
            if (touching || entry.parting) loaded.push_back(static_cast<std::uint32_t>(e));
        });
    collisions_ += begun;
    collectLoaded(cloud);

    // With temperatures tracked, each contact's dissipation heats its particles alike (Eq. 2.117).
    const bool heats = settings_.heating && !cloud.temperature.empty();
    const auto massOf = [&](std::size_t i) {
        return sphereMass(cloud.radius[i], particles_.densityOf(cloud.id[i]));
    };
    const auto count = static_cast<std::ptrdiff_t>(loaded_.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t k = 0; k < count; ++k) {
        const std::size_t i = loaded_[k];
        Vec3 force = Vec3::Zero(), torque = Vec3::Zero();
        double heat = 0; // [K]
        for (std::uint32_t slot = entryStart_[i]; slot < entryStart_[i + 1]; ++slot) {
            const Entry& entry = entries_[entryOf_[slot] / 2];
            if (!entry.touching && !entry.parting) continue;
            const ContactLoad& load = loads_[entryOf_[slot] / 2];
            const bool second = entryOf_[slot] % 2 == 1;
            force += second ? Vec3(-load.force) : load.force;
            torque += second ? load.torqueOnSecond : load.torqueOnFirst;
            if (conducts) // the pair's two flows are equal and opposite
                heat += (second ? -load.conductedPower : load.conductedPower) * dt /
                        (massOf(i) * particles_.specificHeatOf(cloud.id[i]));
            if (heats && load.dissipatedPower > 0) {
                // A wall's side (second < 0) takes none: the first's heat capacity alone.
                const bool pair = entry.second >= 0;
                const auto other = pair ? static_cast<std::size_t>(entry.second) : entry.first;
                heat += collisionalTemperatureRise(
                    load.dissipatedPower * dt,
                    particles_.pairHeatCapacity(cloud.id[entry.first], massOf(entry.first),
                                                cloud.id[other], pair ? massOf(other) : 0.0));
            }
        }
        cloud.contactForce[i] = force;
        cloud.contactTorque[i] = torque;
        if (heats || conducts) cloud.temperature[i] += heat;
    }
}

void SoftSphereCollisions::collectLoaded(ParticleCloud& cloud) {
    // The last call's loads are zeroed where it left them, or everywhere if the cloud changed.
    if (loadedInPlace(cloud)) {
        const auto count = static_cast<std::ptrdiff_t>(loaded_.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelSweep)
        for (std::ptrdiff_t k = 0; k < count; ++k) {
            cloud.contactForce[loaded_[k]] = Vec3::Zero();
            cloud.contactTorque[loaded_[k]] = Vec3::Zero();
        }
    } else {
        fillInParallel(cloud.contactForce, cloud.size(), Vec3(Vec3::Zero()));
        fillInParallel(cloud.contactTorque, cloud.size(), Vec3(Vec3::Zero()));
    }
    // The loaded entries' bodies, ascending and each once.
    fillInParallel(isLoaded_, cloud.size(), std::uint8_t{0});
    for (const std::uint32_t e : loadedEntries_) {
        isLoaded_[entries_[e].first] = 1;
        if (entries_[e].second >= 0) isLoaded_[static_cast<std::size_t>(entries_[e].second)] = 1;
    }
    loaded_ = collectInOrder<std::uint32_t>(
        static_cast<std::ptrdiff_t>(cloud.size()),
        [&](std::ptrdiff_t i, auto& out) {
            if (isLoaded_[i]) out.push_back(static_cast<std::uint32_t>(i));
        },
        minimumParallelSweep);
    loadedIds_.resize(loaded_.size());
    const auto count = static_cast<std::ptrdiff_t>(loaded_.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelSweep)
    for (std::ptrdiff_t k = 0; k < count; ++k) loadedIds_[k] = cloud.id[loaded_[k]];
    loadsListed_ = true;
}

ContactSpring SoftSphereCollisions::springOf(const Entry& entry) const {
    const ParticleId second = entry.second >= 0
                                  ? builtIds_[static_cast<std::size_t>(entry.second)]
                                  : wallId(static_cast<std::size_t>(-1 - entry.second));
    return {builtIds_[entry.first], second, entry.spring.displacement, entry.spring.largestOverlap};
}

std::vector<ContactSpring> SoftSphereCollisions::springs() const {
    std::vector<ContactSpring> touching;
    for (const Entry& entry : entries_)
        if (entry.touching) touching.push_back(springOf(entry));
    std::sort(touching.begin(), touching.end(), byIds);
    return touching;
}

void SoftSphereCollisions::resume(long collisions, std::vector<ContactSpring> springs) {
    collisions_ = collisions;
    pendingSprings_ = std::move(springs);
    loadsListed_ = false; // the checkpoint's loads, on particles not listed
    builtIds_.clear();    // the next step builds the list, handing these springs over
}

} // namespace slides
