#include "slides/integrate/turbulent_dispersion.h"
#include "slides/core/parallel.h"

#include <cstddef>

namespace slides {

TurbulentDispersion::TurbulentDispersion(const PhysicsSettings& physics, std::uint64_t seed)
    : model_(physics.dispersion), constants_(physics.dispersionConstants), seed_(seed) {}

void TurbulentDispersion::perturb(ParticleCloud& cloud, CarrierSample& gas,
                                  const std::vector<double>& stepLengths,
                                  const DragParameters& drag, const Vec3& bodyAcceleration) {
    if (!on()) return;
    cloud.eddy.resize(cloud.size()); // new particles start without an eddy
    fluctuations_.resize(cloud.size());
    const auto count = static_cast<std::ptrdiff_t>(cloud.size());
#pragma omp parallel for schedule(static) if (count >= minimumParallelBatch)
    for (std::ptrdiff_t n = 0; n < count; ++n) {
        const auto i = static_cast<std::size_t>(n);
        const double k = gas.turbulentKineticEnergy[i];
        const double epsilon = gas.dissipationRate[i];
        const RandomKey key{seed_, cloud.id[i]};
        Vec3& fluctuation = fluctuations_[i];
        if (model_ == DispersionModel::langevin) {
            fluctuation = langevinStep(cloud.eddy[i], constants_, k, epsilon, stepLengths[i], key);
        } else {
            const Vec3 slip = cloud.velocity[i] - gas.velocity[i];
            const ParticleResponse particle{
                slip, dragResponseTime(drag, cloud.radius[i], slip.norm()), bodyAcceleration};
            fluctuation = eddyInteractionStep(cloud.eddy[i], constants_, k, epsilon, particle,
                                              stepLengths[i], key);
        }
        gas.velocity[i] += fluctuation;
    }
}

void TurbulentDispersion::addTo(std::span<Vec3> gasVelocity, std::size_t first) const {
    if (!on()) return;
    for (std::size_t i = 0; i < gasVelocity.size(); ++i) gasVelocity[i] += fluctuations_[first + i];
}

} // namespace slides
