#include "slides/integrate/charged_motion.h"

#include "slides/core/parallel.h"
#include "slides/integrate/lorentz_flow.h"

#include <numbers>

namespace slides {

ChargedMotion::ChargedMotion(const ElectromagneticSettings& fields, const DragParameters& drag,
                             const Vec3& bodyAcceleration, double susceptibility)
    : fields_(fields), drag_(drag), bodyAcceleration_(bodyAcceleration),
      susceptibility_(susceptibility) {}

void ChargedMotion::charge(ParticleCloud& cloud, std::size_t first) const {
    cloud.charge.resize(cloud.size());
    for (std::size_t i = first; i < cloud.size(); ++i)
        cloud.charge[i] = fields_.chargeOf(cloud.radius[i], cloud.id[i]);
}

double ChargedMotion::chargeToMassOf(const ParticleCloud& cloud, std::size_t i,
                                     const SpeciesValues& species) const {
    const double radius = cloud.radius[i];
    const double mass =
        4.0 / 3.0 * std::numbers::pi * radius * radius * radius * densityOf(i, species);
    return cloud.charge[i] / mass;
}

LorentzRates ChargedMotion::ratesOf(const ParticleCloud& cloud, std::size_t i,
                                    const SpeciesValues& species) const {
    const double chargeToMass = chargeToMassOf(cloud, i, species);
    return {chargeToMass * fields_.electricField, chargeToMass * fields_.magneticField};
}

ChargedMotion::Forcing ChargedMotion::forcingAt(const ParticleCloud& cloud, std::size_t i,
                                                const SpeciesValues& species, const Vec3& x) const {
    const double chargeToMass = chargeToMassOf(cloud, i, species);
    Vec3 acceleration = chargeToMass * fields_.electricField + accelerationOf(i, species);
    if (fields_.uniform()) return {acceleration, chargeToMass * fields_.magneticField};
    const MagneticFieldSample magnetic = fields_.magneticFieldAt(x);
    if (fields_.magnetisable())
        acceleration += paramagneticAcceleration(
            species.susceptibility.empty() ? susceptibility_ : species.susceptibility[i],
            densityOf(i, species), magnetic.field, magnetic.gradient);
    return {acceleration, chargeToMass * magnetic.field};
}

void ChargedMotion::advance(ParticleCloud& cloud, const CarrierSample& gasStart,
                            const MidpointSampler& sampleMidpoint,
                            const std::vector<double>& stepLengths, const SpeciesValues& species) {
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
    midpoints_.resize(cloud.size());
    midpointVelocities_.resize(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const Vec3& u = gasStart.velocity[i];
        const double tau =
            dragResponseTime(dragOf(i, species), cloud.radius[i], (u - cloud.velocity[i]).norm());
        const Forcing start = forcingAt(cloud, i, species, cloud.position[i]);
        midpoints_[i] = cloud.position[i];
        midpointVelocities_[i] = cloud.velocity[i];
        flowInFields(midpoints_[i], midpointVelocities_[i], u, 1 / tau, start.acceleration,
                     start.gyration, 0.5 * stepLengths[i]);
    }
    sampleMidpoint(midpoints_, gasMidpoint_);
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const Vec3& u = gasMidpoint_.velocity[i];
        const double tau = dragResponseTime(dragOf(i, species), cloud.radius[i],
                                            (u - midpointVelocities_[i]).norm());
        const Forcing midpoint = forcingAt(cloud, i, species, midpoints_[i]);
        flowInFields(cloud.position[i], cloud.velocity[i], u, 1 / tau, midpoint.acceleration,
                     midpoint.gyration, stepLengths[i]);
    }
}

void ChargedMotion::fly(ParticleCloud& cloud, const std::vector<double>& stepLengths,
                        const SpeciesValues& species) const {
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        Forcing forcing = forcingAt(cloud, i, species, cloud.position[i]);
        if (!fields_.uniform()) { // the explicit midpoint rule of the flow
            Vec3 midpoint = cloud.position[i], velocity = cloud.velocity[i];
            flowInFields(midpoint, velocity, Vec3::Zero(), 0.0, forcing.acceleration,
                         forcing.gyration, 0.5 * stepLengths[i]);
            forcing = forcingAt(cloud, i, species, midpoint);
        }
        flowInFields(cloud.position[i], cloud.velocity[i], Vec3::Zero(), 0.0, forcing.acceleration,
                     forcing.gyration, stepLengths[i]);
    }
}

} // namespace slides
