// Particle file: the particles of an injector of model file, one per row, in order of
// injection time. The file's format is told by its content:
//   particlesH5    an HDF5 file (its signature): a previous run's particles.h5, whose arrivals or
//                  a frame's particles in flight become the rows (integrate/previous_run.h);
//   foamPositions  an OpenFOAM file (its FoamFile header): a list of positions as OpenFOAM's
//                  manualInjection reads (integrate/foam_positions.h), all at the injector's
//                  startTime with fileCoeffs.velocity (OpenFOAM's U0) and radii drawn from the
//                  injector's radiusDistribution (OpenFOAM's sizeDistribution), keyed by
//                  (seed, id) as a disc's;
//   csv            anything else: comma- or space-separated, `#` starts a comment line, a
//                  header naming its columns: x y z [m], u v w [m/s], d (diameter) or r (radius)
//                  [m], and optionally t, the injection time after the injector's startTime [s]
//                  (default 0; the rows must not go back in time), wx wy wz the spin [rad/s],
//                  T the temperature [K] and rho the density [kg/m³].
// A file that gives densities (a CSV's rho, a particles.h5's density) makes its rows particles
// of their own species (ParticleSettings::species): the injector's material and specific heat
// with each row's density, one species each distinct density; rows all of one density are one
// species, and if it is the particles' own the run is as without the column. Such an injector
// takes no `density` of its own (the file gives it).
//
//     injectors { ball { model file; file "constant/ball.csv"; } }
//     injectors { target { model file; file "../nozzleRun/slides/particles.h5"; } }
//     injectors { bed { model file; file "constant/kinematicCloudPositions";
//                       fileCoeffs { velocity (0 -1 0); } } }
#pragma once

#include "slides/integrate/injection_settings.h"

#include <filesystem>
#include <vector>

namespace slides {

/// The format of file, from its first bytes; InputError if it cannot be read.
ParticleFileFormat particleFileFormat(const std::filesystem::path& file);

/// Reads the rows of a particle file of injector.file.format into injector (rows, rowsGiveSpin,
/// rowsGiveTemperature, rowsGiveDensity); a bad file throws InputError naming file:line and column
/// or key.
void readParticleFile(const std::filesystem::path& file, InjectorSettings& injector);

} // namespace slides
