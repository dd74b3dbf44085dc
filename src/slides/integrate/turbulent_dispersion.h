// TurbulentDispersion: the step loop's use of the dispersion models (physics/dispersion.h) —
// the gas velocity each particle sees over its step becomes U + ū', ū' the time average of its
// fluctuation over the step, walked through as many eddies as end inside the step.
//
//     physics { dispersion { model eddyInteraction; } }   // none: this does nothing
//
// The stepper samples the carrier (U, k, ε) at the step start, calls perturb() once, which
// gives newly injected particles a fresh eddy state and adds ū' to the sampled velocities, and
// adds the same ū' to its second, midpoint sample (addTo). The eddy crossing uses the
// particle's drag response τ (physics/drag.h) at its step-start slip and the body
// acceleration (of its own species where they differ); the eddy-interaction step runs in SIMD lanes
// (integrate/eddy_batch.h). Random numbers: stream (injection.seed, particle id, eddy, eddy
// counter), so the result does not depend on the thread count and is the same after a restart.
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/core/particle_cloud.h"
#include "slides/integrate/species_values.h"
#include "slides/physics/drag.h"
#include "slides/physics/physics_settings.h"

#include <span>
#include <vector>

namespace slides {

class TurbulentDispersion {
public:
    /// physics.dispersion and its constants; seed: injection.seed, keying the eddy streams.
    TurbulentDispersion(const PhysicsSettings& physics, std::uint64_t seed);

    bool on() const { return model_ != DispersionModel::none; }

    /// For each particle i over its step stepLengths[i]: advances its eddy state and adds ū'
    /// to gas.velocity[i] (gas holds U, k, ε at the particles); species: the particles' own ρp
    /// and body acceleration where they differ, else empty.
    void perturb(ParticleCloud& cloud, CarrierSample& gas, const std::vector<double>& stepLengths,
                 const DragParameters& drag, const Vec3& bodyAcceleration,
                 const SpeciesValues& species);
    /// Adds the ū' of the last perturb() to another sample at the same particles, its entry 0
    /// at particle `first` (a block of the cloud).
    void addTo(std::span<Vec3> gasVelocity, std::size_t first) const;

private:
    DispersionModel model_;
    DispersionConstants constants_;
    std::uint64_t seed_;
    std::vector<Vec3> fluctuations_; ///< ū' of the current step, one per particle
};

} // namespace slides
