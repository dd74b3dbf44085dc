// Previous run: the particles of a previous run's particles.h5 (io/hdf5_particles.h) as the rows
// of an injector of model file, all from the injector's startTime or at their arrival times:
//   arrivals  its /arrivals (position, velocity, diameter, time), in order of arrival: a nozzle
//             run continued by a target run;
//   frame     the particles in flight (state 0) in the frame at a given time, with their
//             position, velocity and diameter, and their spin and temperature where the frame
//             holds them and the new run keeps them, all at the injector's startTime: run A to
//             T, then run B from A's frame at T, continues A's particles.
// Where the previous run's particles differed in density (a `density` dataset in the frame or
// the arrivals), each row keeps its particle's density (integrate/particle_file.h: a species
// per distinct density); else the rows take the injector's.
// The frame at `time` is the one whose time agrees with it to 1e-6 of |time| (the frame at 0 is
// at 0 exactly), so `2e-3` finds the frame the run wrote at 0.0020000000000000005 s.
//
//     injectors { fromA { model file; file "../runA/slides/particles.h5";
//                         fileCoeffs { source frame; time 2e-3; } } }
//
// What a frame does not hold starts afresh: the Basset history memory, eddies, contacts, an
// adaptive step's trial length, and the random streams, which are keyed by the new ids.
#pragma once

#include "slides/integrate/injection_settings.h"

#include <cstddef>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace slides {

/// The times of the frames of a previous run's particles.h5 [s], in order (a stopped run's
/// particles.h5.partial too).
std::vector<double> previousRunFrameTimes(const std::filesystem::path& file);

/// The index of the frame at time (the rule above), if one is.
std::optional<std::size_t> frameAtTime(std::span<const double> times, double time);

/// For messages: "0 0.0005 0.001 s", the first and last few of many with "…" between.
std::string listFrameTimes(std::span<const double> times);

/// Reads the rows (and rowsGiveSpin, rowsGiveTemperature, rowsGiveDensity) that
/// injector.file.source names; a file without them throws InputError naming the file and the
/// dataset.
void readPreviousRun(const std::filesystem::path& file, InjectorSettings& injector);

} // namespace slides
