#include "slides/integrate/turbulent_dispersion.h"
#include "slides/core/parallel.h"
#include "slides/integrate/eddy_batch.h"

#include <cstddef>

namespace slides {

TurbulentDispersion::TurbulentDispersion(const PhysicsSettings& physics, std::uint64_t seed)
    : model_(physics.dispersion), constants_(physics.dispersionConstants), seed_(seed) {}

void TurbulentDispersion::perturb(ParticleCloud& cloud, CarrierSample& gas,
                                  const std::vector<double>& stepLengths,
                                  const DragParameters& drag, const Vec3& bodyAcceleration,
                                  const SpeciesValues& species) {
    if (!on()) return;
    cloud.eddy.resize(cloud.size()); // new particles start without an eddy
    fluctuations_.resize(cloud.size());
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
    if (model_ == DispersionModel::eddyInteraction)
        eddyInteractionBatch({cloud.eddy, cloud.id, cloud.velocity, gas.velocity,
                              gas.turbulentKineticEnergy, gas.dissipationRate, cloud.radius,
                              stepLengths, fluctuations_, species.density, species.acceleration},
                             constants_, drag, bodyAcceleration, seed_);
    // After the eddy-interaction batch, only a sum a particle is left.
    const std::ptrdiff_t parallelFrom =
        model_ == DispersionModel::langevin ? minimumParallelBatch : minimumParallelSweep;
#pragma omp parallel for schedule(static) if (count >= parallelFrom)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        if (model_ == DispersionModel::langevin)
            fluctuations_[i] =
                langevinStep(cloud.eddy[i], constants_, gas.turbulentKineticEnergy[i],
                             gas.dissipationRate[i], stepLengths[i], RandomKey{seed_, cloud.id[i]});
        gas.velocity[i] += fluctuations_[i];
    }
}

void TurbulentDispersion::addTo(std::span<Vec3> gasVelocity, std::size_t first) const {
    if (!on()) return;
    for (std::size_t i = 0; i < gasVelocity.size(); ++i) gasVelocity[i] += fluctuations_[first + i];
}

} // namespace slides
