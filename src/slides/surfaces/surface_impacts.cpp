#include "slides/surfaces/surface_impacts.h"

#include "slides/collide/impulse.h"
#include "slides/physics/adhesion.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/heat_transfer.h"
#include "slides/physics/restitution.h"
#include "slides/surfaces/plane_contact.h"

#include <cmath>
#include <optional>

namespace slides {

SurfaceImpacts::SurfaceImpacts(const std::vector<Surface>& surfaces,
                               const CollisionSettings& collisions,
                               const AdhesionSettings& deposition,
                               const ParticleSettings& particles, HeatTransferModel heatTransfer,
                               const CarrierField& carrier)
    : surfaces_(surfaces), collisions_(collisions), deposition_(deposition), particles_(particles),
      heatTransfer_(heatTransfer), rebounds_(surfaces.size(), 0) {
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        const Surface& surface = surfaces[s];
        walls_.push_back(surface.patch.empty()
                             ? std::nullopt
                             : std::optional<PatchWall>(carrier.patchTriangles(surface.patch)));
        if (!meetsBySoftContact(collisions, surface.interaction)) metAtTouch_.push_back(s);
        erosion_.push_back(surface.interaction == SurfaceInteraction::erode
                               ? std::optional<ErosionGrid>(std::in_place, surface.point,
                                                            surface.normal, surface.material,
                                                            surface.erosion)
                               : std::nullopt);
    }
}

ImpactResult SurfaceImpacts::meet(ParticleCloud& cloud, std::size_t i, const Vec3& start,
                                  const Vec3& startVelocity, double stepLength, double stepEnd,
                                  const std::optional<StepTemperature>& temperature,
                                  Arrival& arrival) {
    // Soft walls meet particles by forces (collide/); with only those, nothing is met here, and
    // the deposit, which only surfaces met here fill, stays empty.
    if (metAtTouch_.empty()) return ImpactResult::none;
    Path path{start, startVelocity, stepLength};
    ImpactResult result = ImpactResult::none;
    // A rebound can meet another surface, or the deposit, in the rest of the step.
    for (int contact = 0; contact < maxContactsPerStep; ++contact) {
        const ImpactResult impact = meetFirst(cloud, i, path, stepEnd, arrival);
        if (impact == ImpactResult::arrived && !cloud.angularVelocity.empty())
            arrival.angularVelocity = cloud.angularVelocity[i];
        if (impact == ImpactResult::arrived && temperature) {
            const double elapsed = 1 - (stepEnd - arrival.time) / stepLength;
            arrival.temperature = temperatureWithinStep(temperature->start, cloud.temperature[i],
                                                        temperature->gas, elapsed);
            // Sticking dissipates all the kinetic energy it arrived with.
            const Surface& plane = surfaces_[static_cast<std::size_t>(arrival.surface)];
            if (plane.interaction == SurfaceInteraction::deposit && heats()) {
                const double mass = sphereMass(arrival.radius, particles_.densityOf(arrival.id));
                const ImpactBody stuck{arrival.velocity, cloud.angularVelocity[i], 1 / mass,
                                       arrival.radius};
                arrival.temperature += collisionalTemperatureRise(
                    kineticEnergy(stuck), particles_.specificHeatOf(arrival.id) * mass);
            }
        }
        if (impact != ImpactResult::rebounded)
            return impact == ImpactResult::none ? result : impact;
        result = ImpactResult::rebounded;
    }
    return result;
}

bool SurfaceImpacts::mayTouch(const Vec3& start, const Vec3& end, double radius) const {
    for (const std::size_t s : metAtTouch_) {
        const bool touches =
            walls_[s]
                ? walls_[s]
                      ->firstTouch(start, end, radius, [](double, const Vec3&) { return true; })
                      .has_value()
                : planeContactFraction(surfaces_[s], start, end, radius).has_value();
        if (touches) return true;
    }
    return deposit_.firstTouch(start, end, radius).has_value();
}

std::optional<PatchTouch> SurfaceImpacts::overlapWith(std::size_t s, const Vec3& centre,
                                                      double radius) const {
    if (walls_[s])
        return walls_[s]->firstTouch(centre, centre, radius,
                                     [](double, const Vec3&) { return true; });
    const Surface& plane = surfaces_[s];
    const double height = (centre - plane.point).dot(plane.normal);
    if (height >= radius) return std::nullopt;
    return PatchTouch{0, plane.normal, plane.point};
}

namespace {

/// Loads the layer with an impact at contact: the surface takes −J, pressed along −n̂ and
/// pulled along the tangential part of −J.
void erode(ErosionGrid& layer, double time, const Vec3& contact, const Vec3& normal,
           const Vec3& impulse, double radius, double mass, const MaterialSettings& particle,
           double normalSpeed) {
    const double normalImpulse = impulse.dot(normal);
    const Vec3 tangential = impulse - normalImpulse * normal;
    const double ratio = tangential.norm() / normalImpulse;
    const Vec3 tangent = ratio > 1e-12 ? Vec3(-tangential.normalized()) : Vec3(layer.axes().col(0));
    layer.applyImpact(time, contact, tangent,
                      layer.impactLoad(radius, mass, particle, normalSpeed, ratio));
}

} // namespace

ImpactResult SurfaceImpacts::meetFirst(ParticleCloud& cloud, std::size_t i, Path& path,
                                       double stepEnd, Arrival& arrival) {
    Vec3& x = cloud.position[i];
    Vec3& v = cloud.velocity[i];
    const double radius = cloud.radius[i];
    const auto velocityAt = [&](double s) -> Vec3 {
        return path.velocity + s * (v - path.velocity);
    };
    const auto centreAt = [&](double s) -> Vec3 { return path.start + s * (x - path.start); };
    // The velocity that meets a surface whose outward direction is `away` at fraction s: the
    // chord's, or, for a path that a collision bent within the step (or that starts in
    // contact), the end velocity. A path that starts in contact and leaves is not met (none);
    // one that reaches the surface within the step always is: when a collision within the step
    // turned both velocities away, with the mean velocity of the chord, which approaches.
    const auto meetingVelocity = [&](double s, const Vec3& away) -> std::optional<Vec3> {
        const Vec3 along = velocityAt(s);
        if (s > 0 && along.dot(away) < 0) return along;
        if (v.dot(away) < 0) return Vec3(v);
        if (s > 0) return Vec3((x - path.start) / path.length);
        return std::nullopt;
    };
    // Only a touch while approaching counts: one that starts on a surface and leaves does not.
    int surface = -1;
    double fraction = 2.0;
    Vec3 contactVelocity = Vec3::Zero();
    Vec3 wallNormal = Vec3::UnitX(), wallPoint = Vec3::Zero(); // the touched plane
    for (const std::size_t s : metAtTouch_) {
        const Surface& plane = surfaces_[s];
        // A sink takes whatever touches it, as before collisions existed.
        const auto meeting = [&](double touch, const Vec3& normal) {
            return plane.interaction == SurfaceInteraction::absorb
                       ? std::optional<Vec3>(velocityAt(touch))
                       : meetingVelocity(touch, normal);
        };
        std::optional<PatchTouch> touch;
        if (walls_[s]) {
            touch = walls_[s]->firstTouch(path.start, x, radius, [&](double at, const Vec3& n) {
                return meeting(at, n).has_value();
            });
        } else if (const auto at = planeContactFraction(plane, path.start, x, radius)) {
            touch = PatchTouch{*at, plane.normal, plane.point};
        }
        if (!touch || touch->fraction >= fraction) continue;
        if (const auto velocity = meeting(touch->fraction, touch->normal)) {
            fraction = touch->fraction;
            surface = static_cast<int>(s);
            contactVelocity = *velocity;
            wallNormal = touch->normal;
            wallPoint = touch->point;
        }
    }
    const auto depositTouch = deposit_.firstTouch(path.start, x, radius);
    bool onDeposit = false;
    if (depositTouch && depositTouch->fraction < fraction) {
        const Vec3 away =
            centreAt(depositTouch->fraction) - deposit_.position(depositTouch->particle);
        if (const auto meeting = meetingVelocity(depositTouch->fraction, away)) {
            onDeposit = true;
            contactVelocity = *meeting;
            fraction = depositTouch->fraction;
            surface = deposit_.surface(depositTouch->particle);
        }
    }
    if (surface < 0) return ImpactResult::none;

    const Surface& plane = surfaces_[static_cast<std::size_t>(surface)];
    const Vec3 normal =
        onDeposit ? (centreAt(fraction) - deposit_.position(depositTouch->particle)).normalized()
                  : wallNormal;
    // At the touch the spheres just meet; a path that started overlapping is set back to that.
    Vec3 centre = onDeposit
                      ? Vec3(deposit_.position(depositTouch->particle) +
                             (radius + deposit_.radius(depositTouch->particle)) * normal)
                      : Vec3(centreAt(fraction) -
                             ((centreAt(fraction) - wallPoint).dot(normal) - radius) * normal);
    // Set back along a line of centres that points into the deposit's plane (a sphere that
    // started against a deposited one and the plane at once), it would sink into the plane:
    // it rests on the plane instead.
    if (onDeposit) {
        if (const auto below = overlapWith(static_cast<std::size_t>(surface), centre, radius))
            centre += (radius - (centre - below->point).dot(below->normal)) * below->normal;
    }
    const double temperature = cloud.temperature.empty() ? 0.0 : cloud.temperature[i];
    const auto arrive = [&] {
        arrival = {cloud.id[i], surface,         stepEnd - (1 - fraction) * path.length,
                   centre,      contactVelocity, radius,
                   temperature};
        return ImpactResult::arrived;
    };
    if (plane.interaction == SurfaceInteraction::absorb) return arrive();

    const double normalSpeed = -contactVelocity.dot(normal);
    // The particle's own species; a deposited particle met is of its own (Eq. 5.9).
    const double mass = sphereMass(radius, particles_.densityOf(cloud.id[i]));
    const MaterialSettings& particleMaterial = particles_.materialOf(cloud.id[i]);
    const ContactBody particle{mass, radius, &particleMaterial};
    const auto depositMaterial = [&]() -> const MaterialSettings& {
        if (particles_.alike()) return particles_.material;
        const auto species = deposit_.species(depositTouch->particle);
        return particles_.species[static_cast<std::size_t>(species)].material;
    };
    const ContactPair pair =
        onDeposit ? contactPair(particle, {INFINITY, deposit_.radius(depositTouch->particle),
                                           &depositMaterial()})
                  : contactPair(particle, {INFINITY, INFINITY, &plane.material});
    const RestitutionSettings& restitution = collisions_.restitution;
    if (plane.interaction == SurfaceInteraction::deposit &&
        sticks(deposition_, restitution, pair, normalSpeed)) {
        deposit_.add(centre, radius, surface, particles_.speciesOf(cloud.id[i]));
        return arrive();
    }

    ImpactBody body{contactVelocity, cloud.angularVelocity[i], 1 / mass, radius};
    ImpactBody rigid;
    const double e = restitutionCoefficient(restitution, pair, normalSpeed);
    const Vec3 impulse = contactImpulse(body, rigid, normal, e, collisions_.friction);
    const double energyBefore = kineticEnergy(body);
    applyImpulse(body, rigid, normal, impulse);
    if (heats())
        cloud.temperature[i] += collisionalTemperatureRise(
            energyBefore - kineticEnergy(body), particles_.specificHeatOf(cloud.id[i]) * mass);
    if (erosion_[static_cast<std::size_t>(surface)] && !onDeposit)
        erode(*erosion_[static_cast<std::size_t>(surface)], stepEnd - (1 - fraction) * path.length,
              centre - radius * normal, normal, impulse, radius, mass, particleMaterial,
              normalSpeed);
    const Vec3 change = body.velocity - contactVelocity;
    const double remaining = (1 - fraction) * path.length;
    v += change;
    x += remaining * change;
    cloud.angularVelocity[i] = body.angularVelocity;
    path = {centre, body.velocity, remaining};
    ++rebounds_[static_cast<std::size_t>(surface)];
    return ImpactResult::rebounded;
}

} // namespace slides
