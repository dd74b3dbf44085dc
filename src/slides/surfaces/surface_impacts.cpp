#include "slides/surfaces/surface_impacts.h"

#include "slides/collide/impulse.h"
#include "slides/physics/adhesion.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/restitution.h"
#include "slides/surfaces/plane_contact.h"

#include <cmath>

namespace slides {

SurfaceImpacts::SurfaceImpacts(const Scene& scene)
    : scene_(scene), rebounds_(scene.surfaces.size(), 0) {}

ImpactResult SurfaceImpacts::meet(ParticleCloud& cloud, std::size_t i, const Vec3& start,
                                  const Vec3& startVelocity, double stepLength, double stepEnd,
                                  Arrival& arrival) {
    Vec3& x = cloud.position[i];
    Vec3& v = cloud.velocity[i];
    const double radius = cloud.radius[i];
    int surface = -1;
    double fraction = 2.0;
    for (std::size_t s = 0; s < scene_.surfaces.size(); ++s) {
        const auto touch = planeContactFraction(scene_.surfaces[s], start, x, radius);
        if (touch && *touch < fraction) {
            fraction = *touch;
            surface = static_cast<int>(s);
        }
    }
    const auto depositTouch = deposit_.firstTouch(start, x, radius);
    const bool onDeposit = depositTouch && depositTouch->fraction < fraction;
    if (onDeposit) {
        fraction = depositTouch->fraction;
        surface = deposit_.surface(depositTouch->particle);
    }
    if (surface < 0) return ImpactResult::none;

    const PlaneSurface& plane = scene_.surfaces[static_cast<std::size_t>(surface)];
    const Vec3 centre = start + fraction * (x - start);
    const Vec3 contactVelocity = startVelocity + fraction * (v - startVelocity);
    const double temperature = cloud.temperature.empty() ? 0.0 : cloud.temperature[i];
    const auto arrive = [&] {
        arrival = {cloud.id[i], surface,         stepEnd - (1 - fraction) * stepLength,
                   centre,      contactVelocity, radius,
                   temperature};
        return ImpactResult::arrived;
    };
    if (plane.interaction == SurfaceInteraction::absorb) return arrive();

    const Vec3 normal = onDeposit
                            ? (centre - deposit_.position(depositTouch->particle)).normalized()
                            : plane.normal;
    const double normalSpeed = -contactVelocity.dot(normal);
    if (normalSpeed <= 0) return ImpactResult::none; // touching, but moving away
    const double mass = 4.0 / 3.0 * M_PI * radius * radius * radius * scene_.particles.density;
    const MaterialSettings& particleMaterial = scene_.particles.material;
    const ContactBody particle{mass, radius, &particleMaterial};
    const ContactPair pair =
        onDeposit ? contactPair(particle, {INFINITY, deposit_.radius(depositTouch->particle),
                                           &particleMaterial})
                  : contactPair(particle, {INFINITY, INFINITY, &plane.material});
    const RestitutionSettings& restitution = scene_.collisions.restitution;
    if (plane.interaction == SurfaceInteraction::deposit &&
        sticks(scene_.deposition, restitution, pair, normalSpeed)) {
        deposit_.add(centre, radius, surface);
        return arrive();
    }

    ImpactBody body{contactVelocity, cloud.angularVelocity[i], 1 / mass, radius};
    ImpactBody rigid;
    const double e = restitutionCoefficient(restitution, pair, normalSpeed);
    const Vec3 impulse = contactImpulse(body, rigid, normal, e, scene_.collisions.friction);
    applyImpulse(body, rigid, normal, impulse);
    const Vec3 change = body.velocity - contactVelocity;
    v += change;
    x += (1 - fraction) * stepLength * change;
    cloud.angularVelocity[i] = body.angularVelocity;
    ++rebounds_[static_cast<std::size_t>(surface)];
    return ImpactResult::rebounded;
}

} // namespace slides
