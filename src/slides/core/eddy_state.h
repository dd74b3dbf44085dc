// EddyState: the per-particle state of turbulent dispersion (physics/dispersion.h), kept in
// ParticleCloud::eddy only while a dispersion model is on.
#pragma once

#include "slides/core/vector.h"

#include <cstdint>

namespace slides {

struct EddyState {
    /// Fluctuation of the current eddy (eddyInteraction) or of the Langevin process, in units
    /// of the local rms fluctuation √(2k/3): the velocity seen is U + √(2k/3)·standardised.
    Vec3 standardised = Vec3::Zero();
    double timeLeft = 0;     ///< eddy lifetime still to run [s]; ≤ 0: draw a new eddy
    double lengthLeft = 0;   ///< path relative to the eddy still to cover before crossing it [m]
    std::uint32_t count = 0; ///< random events drawn so far: the counter of the random stream
};

} // namespace slides
