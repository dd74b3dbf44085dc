// Particle file: the particles of an injector of model file, one per row, in order of
// injection time.
//
//     injectors { ball { model file; file "constant/ball.csv"; } }
//     injectors { target { model file; file "../nozzleRun/slides/particles.h5"; } }
//
// A CSV file (comma- or space-separated; `#` starts a comment line) opens with a header naming
// its columns: x y z [m], u v w [m/s], d (diameter) or r (radius) [m], and optionally t, the
// injection time after the injector's startTime [s] (default 0; the rows must not go back in
// time), wx wy wz the spin [rad/s] and T the temperature [K]. A `.h5` file is a previous run's
// particles.h5: its /arrivals (position, velocity, diameter, time) become the rows, in order of
// arrival, so a nozzle run can be continued by a target run (positions and velocities carried bit
// for bit).
#pragma once

#include "slides/integrate/injection_settings.h"

#include <filesystem>
#include <vector>

namespace slides {

/// Reads the rows of a particle file into injector (rows, rowsGiveSpin, rowsGiveTemperature); a
/// bad file throws InputError naming file:line and column.
void readParticleFile(const std::filesystem::path& file, InjectorSettings& injector);

} // namespace slides
