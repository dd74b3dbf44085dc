#include "slides/integrate/previous_run.h"

#include "slides/core/error.h"
#include "slides/io/hdf5_file.h"
#include "slides/io/hdf5_particles.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace slides {

namespace {

/// Runs read(file) and turns what the HDF5 layer throws into one InputError naming the file and
/// the object read.
template <typename Read>
void readOrRefuse(const std::filesystem::path& path, const std::string& object, Read read) {
    try {
        const Hdf5File file(path, Hdf5Access::readOnly);
        read(file);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& error) {
        throw InputError(path.string(), 0, object,
                         std::string("not a readable particles.h5: ") + error.what());
    }
}

/// Throws unless every dataset of a frame or of /arrivals has count rows.
void requireRows(const std::filesystem::path& path, const std::string& group, std::size_t count,
                 std::initializer_list<std::size_t> lengths) {
    for (const std::size_t length : lengths)
        if (length != count)
            throw InputError(path.string(), 0, group, "datasets of different lengths");
}

/// The arrivals of a previous run's particles.h5, in order of arrival, with their densities
/// where the run wrote them (its particles differed).
void readArrivals(const std::filesystem::path& path, InjectorSettings& injector) {
    std::vector<double> positions, velocities, diameters, times, densities;
    readOrRefuse(path, "/arrivals", [&](const Hdf5File& file) {
        if (!file.exists("/arrivals"))
            throw InputError(path.string(), 0, "/arrivals", "no arrivals: the run did not finish");
        positions = file.readDoubles("/arrivals/position", 3);
        velocities = file.readDoubles("/arrivals/velocity", 3);
        diameters = file.readDoubles("/arrivals/diameter", 1);
        times = file.readDoubles("/arrivals/time", 1);
        if (file.exists("/arrivals/density")) densities = file.readDoubles("/arrivals/density", 1);
    });
    const std::size_t count = diameters.size();
    injector.rowsGiveSpin = injector.rowsGiveTemperature = false;
    injector.rowsGiveDensity = !densities.empty();
    requireRows(path, "/arrivals", count,
                {positions.size() / 3, velocities.size() / 3, times.size(),
                 injector.rowsGiveDensity ? densities.size() : count});
    if (count == 0) throw InputError(path.string(), 0, "/arrivals", "no particle arrived");
    std::vector<ParticleRow>& rows = injector.rows;
    rows.assign(count, ParticleRow{});
    for (std::size_t i = 0; i < count; ++i) {
        rows[i].position = Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        rows[i].velocity = Vec3(velocities[3 * i], velocities[3 * i + 1], velocities[3 * i + 2]);
        rows[i].radius = 0.5 * diameters[i];
        rows[i].time = times[i];
        if (injector.rowsGiveDensity) rows[i].density = densities[i];
    }
    std::stable_sort(rows.begin(), rows.end(),
                     [](const ParticleRow& a, const ParticleRow& b) { return a.time < b.time; });
}

/// The particles in flight in frame index, all at time 0 after the injector's start.
void readFrame(const std::filesystem::path& path, std::size_t index, InjectorSettings& injector) {
    const std::string group = particlesFrameGroup(index);
    std::vector<double> positions, velocities, diameters, spins, temperatures, densities;
    std::vector<std::int32_t> states;
    double time = 0;
    readOrRefuse(path, group, [&](const Hdf5File& file) {
        const auto required = [&](const std::string& name) {
            const std::string dataset = group + "/" + name;
            if (!file.exists(dataset))
                throw InputError(path.string(), 0, dataset,
                                 "missing: the run wrote its frames without " + name +
                                     " (output.fields)");
            return dataset;
        };
        time = file.readDouble(group, "time");
        positions = file.readDoubles(group + "/position", 3);
        velocities = file.readDoubles(required("velocity"), 3);
        diameters = file.readDoubles(required("diameter"), 1);
        states = file.readInt32(required("state"));
        if (file.exists(group + "/angularVelocity"))
            spins = file.readDoubles(group + "/angularVelocity", 3);
        if (file.exists(group + "/temperature"))
            temperatures = file.readDoubles(group + "/temperature", 1);
        if (file.exists(group + "/density")) densities = file.readDoubles(group + "/density", 1);
    });
    const std::size_t count = diameters.size();
    injector.rowsGiveSpin = !spins.empty();
    injector.rowsGiveTemperature = !temperatures.empty();
    injector.rowsGiveDensity = !densities.empty();
    requireRows(path, group, count,
                {positions.size() / 3, velocities.size() / 3, states.size(),
                 injector.rowsGiveSpin ? spins.size() / 3 : count,
                 injector.rowsGiveTemperature ? temperatures.size() : count,
                 injector.rowsGiveDensity ? densities.size() : count});
    std::vector<ParticleRow>& rows = injector.rows;
    rows.clear();
    for (std::size_t i = 0; i < count; ++i) {
        if (states[i] != 0) continue; // arrived: frozen where it touched
        ParticleRow row;
        row.position = Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        row.velocity = Vec3(velocities[3 * i], velocities[3 * i + 1], velocities[3 * i + 2]);
        row.radius = 0.5 * diameters[i]; // exact: the diameter was written as 2 r
        if (injector.rowsGiveSpin)
            row.angularVelocity = Vec3(spins[3 * i], spins[3 * i + 1], spins[3 * i + 2]);
        if (injector.rowsGiveTemperature) row.temperature = temperatures[i];
        if (injector.rowsGiveDensity) row.density = densities[i];
        rows.push_back(row);
    }
    if (rows.empty()) {
        char message[96];
        std::snprintf(message, sizeof message, "no particle in flight at t = %.7g s", time);
        throw InputError(path.string(), 0, group, message);
    }
}

} // namespace

std::vector<double> previousRunFrameTimes(const std::filesystem::path& file) {
    std::vector<double> times;
    readOrRefuse(file, "/frames", [&](const Hdf5File& h5) {
        if (!h5.exists("/frames"))
            throw InputError(file.string(), 0, "/frames", "no frames: not a particles.h5");
        for (std::size_t index = 0; h5.exists(particlesFrameGroup(index)); ++index)
            times.push_back(h5.readDouble(particlesFrameGroup(index), "time"));
    });
    return times;
}

std::optional<std::size_t> frameAtTime(std::span<const double> times, double time) {
    std::optional<std::size_t> nearest;
    for (std::size_t k = 0; k < times.size(); ++k) {
        const double distance = std::abs(times[k] - time);
        if (distance <= 1e-6 * std::abs(time) &&
            (!nearest || distance < std::abs(times[*nearest] - time)))
            nearest = k;
    }
    return nearest;
}

std::string listFrameTimes(std::span<const double> times) {
    constexpr std::size_t shownAtEachEnd = 6;
    std::string list;
    char time[32];
    for (std::size_t k = 0; k < times.size(); ++k) {
        if (times.size() > 2 * shownAtEachEnd && k == shownAtEachEnd) {
            list += " …";
            k = times.size() - shownAtEachEnd;
        }
        std::snprintf(time, sizeof time, " %.7g", times[k]);
        list += time;
    }
    return times.empty() ? "none" : list.substr(1) + " s";
}

void readPreviousRun(const std::filesystem::path& file, InjectorSettings& injector) {
    if (injector.file.source == PreviousRunSource::frame) {
        readFrame(file, injector.file.frame, injector);
        return;
    }
    readArrivals(file, injector);
}

} // namespace slides
