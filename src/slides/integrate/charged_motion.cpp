#include "slides/integrate/charged_motion.h"

#include "slides/core/parallel.h"
#include "slides/integrate/lorentz_flow.h"

#include <numbers>

namespace slides {

ChargedMotion::ChargedMotion(const ElectromagneticSettings& fields, const DragParameters& drag,
                             const Vec3& bodyAcceleration)
    : fields_(fields), drag_(drag), bodyAcceleration_(bodyAcceleration) {}

void ChargedMotion::charge(ParticleCloud& cloud, std::size_t first) const {
    cloud.charge.resize(cloud.size());
    for (std::size_t i = first; i < cloud.size(); ++i)
        cloud.charge[i] = fields_.chargeOf(cloud.radius[i], cloud.id[i]);
}

LorentzRates ChargedMotion::ratesOf(const ParticleCloud& cloud, std::size_t i,
                                    const SpeciesValues& species) const {
    const double radius = cloud.radius[i];
    const double density = species.alike() ? drag_.particleDensity : species.density[i];
    const double mass = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius * density;
    return lorentzRates(fields_, cloud.charge[i], mass);
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
        const LorentzRates rates = ratesOf(cloud, i, species);
        midpoints_[i] = cloud.position[i];
        midpointVelocities_[i] = cloud.velocity[i];
        flowInFields(midpoints_[i], midpointVelocities_[i], u, 1 / tau,
                     rates.electricAcceleration + accelerationOf(i, species), rates.gyration,
                     0.5 * stepLengths[i]);
    }
    sampleMidpoint(midpoints_, gasMidpoint_);
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const Vec3& u = gasMidpoint_.velocity[i];
        const double tau = dragResponseTime(dragOf(i, species), cloud.radius[i],
                                            (u - midpointVelocities_[i]).norm());
        const LorentzRates rates = ratesOf(cloud, i, species);
        flowInFields(cloud.position[i], cloud.velocity[i], u, 1 / tau,
                     rates.electricAcceleration + accelerationOf(i, species), rates.gyration,
                     stepLengths[i]);
    }
}

void ChargedMotion::fly(ParticleCloud& cloud, const std::vector<double>& stepLengths,
                        const SpeciesValues& species) const {
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const LorentzRates rates = ratesOf(cloud, i, species);
        flowInFields(cloud.position[i], cloud.velocity[i], Vec3::Zero(), 0.0,
                     rates.electricAcceleration + accelerationOf(i, species), rates.gyration,
                     stepLengths[i]);
    }
}

} // namespace slides
