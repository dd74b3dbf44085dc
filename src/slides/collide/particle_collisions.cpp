#include "slides/collide/particle_collisions.h"

#include "slides/collide/impulse.h"
#include "slides/collide/swept_contact.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/restitution.h"

#include <algorithm>
#include <cmath>
#include <optional>

namespace slides {

ParticleCollisions::ParticleCollisions(const CollisionSettings& collisions,
                                       const ParticleSettings& particles)
    : settings_(collisions), particles_(particles) {}

void ParticleCollisions::findContacts(const ParticleCloud& cloud,
                                      const std::vector<Vec3>& startPositions) {
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
    double largestRadius = 0, longestChord = 0;
    midpoints_.resize(cloud.size());
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        largestRadius = std::max(largestRadius, cloud.radius[i]);
        longestChord = std::max(longestChord, (cloud.position[i] - startPositions[i]).norm());
        midpoints_[i] = 0.5 * (startPositions[i] + cloud.position[i]);
    }
    // Spheres touching at fraction s are |d(s)| = R_a + R_b apart, and their chords' midpoints
    // at most that plus |s − ½| |Δd| ≤ d_max further: cells of 2 R_max + d_max hold every pair.
    grid_.build(midpoints_, 2 * largestRadius + longestChord);

    contacts_ = collectPairs<ParticleContact>(grid_, [&](std::uint32_t s, std::uint32_t t) {
        const std::uint32_t a = grid_.pointAt(s), b = grid_.pointAt(t);
        const auto fraction = sweptContactFraction(startPositions[a] - startPositions[b],
                                                   cloud.position[a] - cloud.position[b],
                                                   cloud.radius[a] + cloud.radius[b]);
        return fraction ? std::optional<ParticleContact>({a, b, *fraction}) : std::nullopt;
    });
    // Earliest touch first; ties by particle id, which, unlike an index, a run never reorders.
    const auto key = [&](const ParticleContact& c) {
        const ParticleId first = cloud.id[c.a], second = cloud.id[c.b];
        return std::make_tuple(c.fraction, std::min(first, second), std::max(first, second));
    };
    std::sort(contacts_.begin(), contacts_.end(),
              [&](const ParticleContact& x, const ParticleContact& y) { return key(x) < key(y); });
}

void ParticleCollisions::collide(ParticleCloud& cloud, const std::vector<Vec3>& startPositions,
                                 const std::vector<double>& stepLengths) {
    if (cloud.size() < 2) return;
    findContacts(cloud, startPositions);
    const bool heats = settings_.heating && !cloud.temperature.empty();
    for (const ParticleContact& contact : contacts_) {
        const std::uint32_t a = contact.a, b = contact.b;
        const double s = contact.fraction;
        const Vec3 centreA = startPositions[a] + s * (cloud.position[a] - startPositions[a]);
        const Vec3 centreB = startPositions[b] + s * (cloud.position[b] - startPositions[b]);
        const Vec3 separation = centreA - centreB;
        if (!(separation.squaredNorm() > 0)) continue; // coincident centres: no normal
        const Vec3 normal = separation.normalized();
        // Each particle's own species: its mass, and the pair's moduli from both materials.
        const double massA = sphereMass(cloud.radius[a], particles_.densityOf(cloud.id[a]));
        const double massB = sphereMass(cloud.radius[b], particles_.densityOf(cloud.id[b]));
        ImpactBody bodyA{cloud.velocity[a], cloud.angularVelocity[a], 1 / massA, cloud.radius[a]};
        ImpactBody bodyB{cloud.velocity[b], cloud.angularVelocity[b], 1 / massB, cloud.radius[b]};
        const double approach = -(bodyA.velocity - bodyB.velocity).dot(normal);
        if (approach <= 0) continue;
        const ContactPair pair =
            contactPair({massA, cloud.radius[a], &particles_.materialOf(cloud.id[a])},
                        {massB, cloud.radius[b], &particles_.materialOf(cloud.id[b])});
        const double e = restitutionCoefficient(settings_.restitution, pair, approach);
        const Vec3 impulse = contactImpulse(bodyA, bodyB, normal, e, settings_.friction);
        const double energyBefore = kineticEnergy(bodyA) + kineticEnergy(bodyB);
        applyImpulse(bodyA, bodyB, normal, impulse);
        if (heats) {
            const double dissipated = energyBefore - kineticEnergy(bodyA) - kineticEnergy(bodyB);
            const double rise = collisionalTemperatureRise(
                dissipated, particles_.pairHeatCapacity(cloud.id[a], massA, cloud.id[b], massB));
            cloud.temperature[a] += rise;
            cloud.temperature[b] += rise;
        }
        cloud.position[a] += (1 - s) * stepLengths[a] * (bodyA.velocity - cloud.velocity[a]);
        cloud.position[b] += (1 - s) * stepLengths[b] * (bodyB.velocity - cloud.velocity[b]);
        cloud.velocity[a] = bodyA.velocity;
        cloud.velocity[b] = bodyB.velocity;
        cloud.angularVelocity[a] = bodyA.angularVelocity;
        cloud.angularVelocity[b] = bodyB.angularVelocity;
        ++collisions_;
    }
}

} // namespace slides
