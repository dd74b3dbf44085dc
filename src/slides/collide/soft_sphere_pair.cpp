#include "slides/collide/soft_sphere_pair.h"

namespace slides {

namespace {

/// Load of a contact of overlap δ > 0 with unit normal n (from the second body to the first),
/// the contact point at lever arms l_a, l_b from the two centres, moving with each body.
ContactLoad contactLoad(const ContactPair& pair, const SoftContactLaw& law, double overlap,
                        const Vec3& normal, double leverA, double leverB, const ContactSphere& a,
                        const Vec3& velocityB, const Vec3& spinB, TangentialSpring& spring,
                        double dt) {
    const Vec3 contactVelocityA = a.velocity - leverA * a.spin.cross(normal);
    const Vec3 contactVelocityB = velocityB + leverB * spinB.cross(normal);
    const Vec3 slip = contactVelocityA - contactVelocityB;
    const double closingSpeed = -slip.dot(normal);
    const double normalForce =
        normalContactForce(pair, law, overlap, closingSpeed, dt, spring.largestOverlap);
    const Vec3 tangentialForce =
        mindlinTangentialForce(spring, pair, law, overlap, normal, slip, normalForce, dt);
    const Vec3 nCrossFt = normal.cross(tangentialForce);
    // Dissipation: the normal force beyond the elastic one, and the tangential force's work
    // less what the spring stores (all of it at the Coulomb limit, where the spring stays put).
    const double elasticForce = elasticNormalForce(pair, law, overlap);
    const Vec3 tangentialSlip = slip - slip.dot(normal) * normal;
    const bool sliding = law.regularisation != FrictionRegularisation::none ||
                         tangentialForce.norm() >= law.friction * normalForce * (1 - 1e-12);
    const double storedPower =
        sliding ? 0.0 : mindlinStiffness(pair, overlap) * spring.displacement.dot(tangentialSlip);
    const double tangentialPower = -tangentialForce.dot(tangentialSlip) - storedPower;
    return {overlap, normalForce * normal + tangentialForce, -leverA * nCrossFt, -leverB * nCrossFt,
            (normalForce - elasticForce) * closingSpeed + tangentialPower};
}

/// Load in the step where a contact with unit normal n parted (δ ≤ 0): the dashpot's pull up to
/// the parting (partingNormalForce), or nothing if the contact was not touching at the last load
/// (its spring's δ_max is 0). The spring is reset.
ContactLoad partingLoad(const ContactPair& pair, const SoftContactLaw& law, double overlap,
                        const Vec3& normal, const Vec3& relativeVelocity, TangentialSpring& spring,
                        double dt) {
    const bool parted = spring.largestOverlap > 0;
    spring = {};
    if (!parted) return {overlap};
    const double closingSpeed = -relativeVelocity.dot(normal);
    const double normalForce = partingNormalForce(pair, law, overlap, closingSpeed, dt);
    // The work of the pull, all of it dissipated.
    return {overlap, normalForce * normal, Vec3::Zero(), Vec3::Zero(), normalForce * closingSpeed};
}

} // namespace

ContactLoad sphereSphereLoad(const ContactPair& pair, const SoftContactLaw& law,
                             const ContactSphere& a, const ContactSphere& b,
                             TangentialSpring& spring, double dt) {
    const Vec3 separation = a.position - b.position;
    const double distance = separation.norm();
    const double overlap = a.radius + b.radius - distance;
    if (overlap <= 0)
        return partingLoad(pair, law, overlap, separation / distance, a.velocity - b.velocity,
                           spring, dt);
    // The plane of the overlap lens: lever arms that add up to the centre distance.
    const double leverA =
        (distance * distance + a.radius * a.radius - b.radius * b.radius) / (2.0 * distance);
    return contactLoad(pair, law, overlap, separation / distance, leverA, distance - leverA, a,
                       b.velocity, b.spin, spring, dt);
}

ContactLoad sphereWallLoad(const ContactPair& pair, const SoftContactLaw& law,
                           const ContactSphere& sphere, const Vec3& wallPoint,
                           const Vec3& wallNormal, TangentialSpring& spring, double dt) {
    const double distance = (sphere.position - wallPoint).dot(wallNormal);
    const double overlap = sphere.radius - distance;
    if (overlap <= 0)
        return partingLoad(pair, law, overlap, wallNormal, sphere.velocity, spring, dt);
    return contactLoad(pair, law, overlap, wallNormal, distance, 0.0, sphere, Vec3::Zero(),
                       Vec3::Zero(), spring, dt);
}

} // namespace slides
