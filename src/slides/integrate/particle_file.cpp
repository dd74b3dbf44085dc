#include "slides/integrate/particle_file.h"

#include "slides/core/error.h"
#include "slides/integrate/csv_table.h"
#include "slides/io/hdf5_file.h"

#include <algorithm>
#include <string>

namespace slides {

namespace {

std::vector<ParticleRow> readCsv(const std::filesystem::path& path, InjectorSettings& injector) {
    const CsvTable table =
        readCsvTable(path, {"x", "y", "z", "u", "v", "w", "d", "r", "t", "wx", "wy", "wz", "T"});
    for (const char* name : {"x", "y", "z", "u", "v", "w"})
        if (!table.column(name))
            table.fail(0, name, "missing column (the header needs x y z u v w, d or r)");
    const auto diameter = table.column("d"), radius = table.column("r"), time = table.column("t");
    if (diameter.has_value() == radius.has_value())
        table.fail(0, "d", "give the diameter d or the radius r, one of them");
    const int spinColumns = int(table.column("wx").has_value()) +
                            int(table.column("wy").has_value()) +
                            int(table.column("wz").has_value());
    if (spinColumns % 3 != 0) table.fail(0, "wx", "give the spin as wx wy wz, all three");
    injector.rowsGiveSpin = spinColumns == 3;
    injector.rowsGiveTemperature = table.column("T").has_value();
    const auto at = [&](const std::vector<double>& row, const char* name) {
        return row[*table.column(name)];
    };
    std::vector<ParticleRow> rows;
    for (std::size_t k = 0; k < table.rows.size(); ++k) {
        const std::vector<double>& values = table.rows[k];
        ParticleRow row;
        row.position = Vec3(at(values, "x"), at(values, "y"), at(values, "z"));
        row.velocity = Vec3(at(values, "u"), at(values, "v"), at(values, "w"));
        row.radius = diameter ? 0.5 * values[*diameter] : values[*radius];
        row.time = time ? values[*time] : 0.0;
        if (injector.rowsGiveSpin)
            row.angularVelocity = Vec3(at(values, "wx"), at(values, "wy"), at(values, "wz"));
        if (injector.rowsGiveTemperature) row.temperature = at(values, "T");
        if (injector.rowsGiveTemperature && !(row.temperature > 0))
            table.fail(k, "T", "must be a positive number (kelvin)");
        if (!(row.radius > 0)) table.fail(k, diameter ? "d" : "r", "must be a positive number");
        if (row.time < 0) table.fail(k, "t", "must not be negative");
        if (!rows.empty() && row.time < rows.back().time)
            table.fail(k, "t", "goes back in time: rows must be in order of injection time");
        rows.push_back(row);
    }
    return rows;
}

/// The arrivals of a previous run's particles.h5, in order of arrival.
std::vector<ParticleRow> readArrivals(const std::filesystem::path& path) {
    const auto refuse = [&](const std::string& message) {
        throw InputError(path.string(), 0, "/arrivals", message);
    };
    std::vector<double> positions, velocities, diameters, times;
    try {
        const Hdf5File file(path, Hdf5Access::readOnly);
        if (!file.exists("/arrivals")) refuse("no arrivals: the run did not finish");
        positions = file.readDoubles("/arrivals/position", 3);
        velocities = file.readDoubles("/arrivals/velocity", 3);
        diameters = file.readDoubles("/arrivals/diameter", 1);
        times = file.readDoubles("/arrivals/time", 1);
    } catch (const InputError&) {
        throw;
    } catch (const std::exception& error) {
        refuse(std::string("not a readable particles.h5: ") + error.what());
    }
    const std::size_t count = diameters.size();
    if (positions.size() != 3 * count || velocities.size() != 3 * count || times.size() != count)
        refuse("datasets of different lengths");
    if (count == 0) refuse("no particle arrived");
    std::vector<ParticleRow> rows(count);
    for (std::size_t i = 0; i < count; ++i) {
        rows[i].position = Vec3(positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]);
        rows[i].velocity = Vec3(velocities[3 * i], velocities[3 * i + 1], velocities[3 * i + 2]);
        rows[i].radius = 0.5 * diameters[i];
        rows[i].time = times[i];
    }
    std::stable_sort(rows.begin(), rows.end(),
                     [](const ParticleRow& a, const ParticleRow& b) { return a.time < b.time; });
    return rows;
}

} // namespace

void readParticleFile(const std::filesystem::path& file, InjectorSettings& injector) {
    injector.rows = file.extension() == ".h5" ? readArrivals(file) : readCsv(file, injector);
}

} // namespace slides
