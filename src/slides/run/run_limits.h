// Run limits: the size of a run (steps, frames, memory) against documented bounds, checked
// before anything is written.
//
// A step count past 1e9 or a frame count past 1e6 would run for days or hang on its output;
// particles or a carrier grid that cannot fit in the machine's memory would fail halfway
// through. Each is an InputError naming the key that sets it, with the figure.
//
//     time { dt 1e-5; endTime 0.1; }   output { interval 5e-4; carrierResolution (141 61 61); }
#pragma once

#include "slides/config/scene.h"

namespace slides {

constexpr double maximumSteps = 1e9;  ///< time.endTime / time.dt
constexpr double maximumFrames = 1e6; ///< time.endTime / output.interval

/// Throws InputError naming time.dt, output.interval, particles.count or
/// output.carrierResolution when the run they set exceeds its bound or the machine's memory.
void requireRunWithinLimits(const Scene& scene);

} // namespace slides
