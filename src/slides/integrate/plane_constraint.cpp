#include "slides/integrate/plane_constraint.h"

#include "slides/core/parallel.h"

#include <cstddef>

namespace slides {

PlaneConstraint::PlaneConstraint(const Vec3& normal, const Box& bounds)
    : normal_(normal.normalized()), midPlane_(0.5 * (bounds.min + bounds.max).dot(normal_)) {}

void PlaneConstraint::hold(ParticleCloud& cloud) const {
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i) {
        cloud.position[i] = onMidPlane(cloud.position[i]);
        cloud.velocity[i] = inPlane(cloud.velocity[i]);
    }
    // Model state, each array as long as its model has filled it (new particles get theirs
    // later in the step): the eddy drawn is kept for the steps to come.
    for (EddyState& eddy : cloud.eddy) eddy.standardised = inPlane(eddy.standardised);
    for (Vec3& spin : cloud.angularVelocity) spin = alongNormal(spin);
    for (Vec3& force : cloud.contactForce) force = inPlane(force);
    for (Vec3& torque : cloud.contactTorque) torque = alongNormal(torque);
}

void PlaneConstraint::project(std::vector<Vec3>& vectors) const {
    const auto count = static_cast<std::ptrdiff_t>(vectors.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t i = 0; i < count; ++i) vectors[i] = inPlane(vectors[i]);
}

std::optional<PlaneConstraint> planeConstraintOf(const CarrierField& carrier) {
    const auto normal = carrier.planeNormal();
    const auto bounds = carrier.bounds();
    if (!normal || !bounds) return std::nullopt;
    return PlaneConstraint(*normal, *bounds);
}

} // namespace slides
