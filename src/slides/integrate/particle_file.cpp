#include "slides/integrate/particle_file.h"

#include "slides/core/error.h"
#include "slides/io/hdf5_file.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace slides {

namespace {

/// The fields of a line split at commas, spaces and tabs.
std::vector<std::string> fieldsOf(const std::string& line) {
    std::vector<std::string> fields;
    std::string field;
    for (const char c : line + ",") {
        if (c == ',' || c == ' ' || c == '\t' || c == '\r') {
            if (!field.empty()) fields.push_back(field);
            field.clear();
        } else {
            field += c;
        }
    }
    return fields;
}

std::vector<ParticleRow> readCsv(const std::filesystem::path& path) {
    std::ifstream in(path);
    if (!in) throw InputError(path.string(), 0, "", "cannot read the particle file");
    const std::array<std::string, 9> known{"x", "y", "z", "u", "v", "w", "d", "r", "t"};
    std::array<std::optional<std::size_t>, 9> column;
    std::vector<ParticleRow> rows;
    std::string line;
    int lineNumber = 0;
    std::size_t width = 0;
    const auto fail = [&](const std::string& key, const std::string& message) {
        throw InputError(path.string(), lineNumber, key, message);
    };
    while (std::getline(in, line)) {
        ++lineNumber;
        const auto fields = fieldsOf(line);
        if (fields.empty() || fields[0].starts_with('#')) continue;
        if (width == 0) { // the header
            width = fields.size();
            for (std::size_t c = 0; c < width; ++c) {
                const auto at = std::find(known.begin(), known.end(), fields[c]);
                if (at == known.end())
                    fail(fields[c], "unknown column; columns are x y z u v w, d or r, t");
                auto& slot = column[static_cast<std::size_t>(at - known.begin())];
                if (slot) fail(fields[c], "column given twice");
                slot = c;
            }
            for (const char* name : {"x", "y", "z", "u", "v", "w"})
                if (!column[static_cast<std::size_t>(std::find(known.begin(), known.end(), name) -
                                                     known.begin())])
                    fail(name, "missing column (the header needs x y z u v w, d or r)");
            if (column[6].has_value() == column[7].has_value())
                fail("d", "give the diameter d or the radius r, one of them");
            continue;
        }
        if (fields.size() != width)
            fail("", std::to_string(fields.size()) + " values, the header names " +
                         std::to_string(width) + " columns");
        std::array<double, 9> value{};
        for (std::size_t k = 0; k < known.size(); ++k) {
            if (!column[k]) continue;
            const std::string& text = fields[*column[k]];
            const auto [end, error] =
                std::from_chars(text.data(), text.data() + text.size(), value[k]);
            if (error != std::errc() || end != text.data() + text.size() ||
                !std::isfinite(value[k]))
                fail(known[k], "expected a finite number, found '" + text + "'");
        }
        ParticleRow row;
        row.position = Vec3(value[0], value[1], value[2]);
        row.velocity = Vec3(value[3], value[4], value[5]);
        row.radius = column[6] ? 0.5 * value[6] : value[7];
        row.time = value[8];
        if (!(row.radius > 0)) fail(column[6] ? "d" : "r", "must be a positive number");
        if (row.time < 0) fail("t", "must not be negative");
        if (!rows.empty() && row.time < rows.back().time)
            fail("t", "goes back in time: rows must be in order of injection time");
        rows.push_back(row);
    }
    if (rows.empty()) fail("", "no particle rows");
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

std::vector<ParticleRow> readParticleFile(const std::filesystem::path& file) {
    return file.extension() == ".h5" ? readArrivals(file) : readCsv(file);
}

} // namespace slides
