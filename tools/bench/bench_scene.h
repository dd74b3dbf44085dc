// The scene the stepper benchmarks time: the default case with every particle injected at the
// start and kept in flight (no surfaces, an unbounded domain, no end in sight).
#pragma once

#include "slides/config/scene_reader.h"

#include <filesystem>

namespace slides::bench {

inline Scene particlesInFlight(long count) {
    Scene scene = readScene(std::filesystem::path(SLIDES_SOURCE_DIR) / "foamCases/analyticSpray");
    scene.particles.count = count;
    scene.injection.mode = InjectionMode::allAtStart;
    scene.time.endTime = 1e9;
    scene.time.stopWhenAllDone = false;
    scene.surfaces.clear(); // keep every particle in flight while timing
    scene.domain = {Vec3::Constant(-1e9), Vec3::Constant(1e9)};
    return scene;
}

} // namespace slides::bench
