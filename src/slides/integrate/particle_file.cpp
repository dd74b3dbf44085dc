#include "slides/integrate/particle_file.h"

#include "slides/config/dictionary_lexer.h"
#include "slides/core/error.h"
#include "slides/integrate/csv_table.h"
#include "slides/integrate/foam_positions.h"
#include "slides/integrate/previous_run.h"
#include "slides/integrate/size_distribution.h"

#include <fstream>
#include <string>
#include <string_view>

namespace slides {

namespace {

std::vector<ParticleRow> readCsv(const std::filesystem::path& path, InjectorSettings& injector) {
    const CsvTable table = readCsvTable(
        path, {"x", "y", "z", "u", "v", "w", "d", "r", "t", "wx", "wy", "wz", "T", "rho"});
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
    injector.rowsGiveDensity = table.column("rho").has_value();
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
        if (injector.rowsGiveDensity) row.density = at(values, "rho");
        if (injector.rowsGiveDensity && !(row.density > 0))
            table.fail(k, "rho", "must be a positive number (kg/m^3)");
        if (!(row.radius > 0)) table.fail(k, diameter ? "d" : "r", "must be a positive number");
        if (row.time < 0) table.fail(k, "t", "must not be negative");
        if (!rows.empty() && row.time < rows.back().time)
            table.fail(k, "t", "goes back in time: rows must be in order of injection time");
        rows.push_back(row);
    }
    return rows;
}

} // namespace

ParticleFileFormat particleFileFormat(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw InputError(file.string(), 0, "", "cannot read the file");
    constexpr std::string_view hdf5Signature("\x89HDF\r\n\x1a\n", 8);
    std::string start(4096, '\0');
    in.read(start.data(), static_cast<std::streamsize>(start.size()));
    start.resize(static_cast<std::size_t>(in.gcount()));
    if (start.starts_with(hdf5Signature)) return ParticleFileFormat::particlesH5;
    // The first token after the banner comment: FoamFile opens an OpenFOAM file.
    try {
        dictionary_syntax::Lexer lexer(start, file.string());
        const dictionary_syntax::Token& first = lexer.peek();
        if (first.kind == dictionary_syntax::Token::Kind::word && first.text == "FoamFile")
            return ParticleFileFormat::foamPositions;
    } catch (const dictionary_syntax::LexFailure&) { // not OpenFOAM text: a CSV table
    }
    return ParticleFileFormat::csv;
}

void readParticleFile(const std::filesystem::path& file, InjectorSettings& injector) {
    switch (injector.file.format) {
    case ParticleFileFormat::csv: injector.rows = readCsv(file, injector); return;
    case ParticleFileFormat::particlesH5: readPreviousRun(file, injector); return;
    case ParticleFileFormat::foamPositions: {
        const std::vector<Vec3> positions =
            readFoamPositions(file, "injectors." + injector.name + ".file");
        const RadiusSampler radius(injector.radius);
        injector.rows.assign(positions.size(), ParticleRow{});
        for (std::size_t k = 0; k < positions.size(); ++k) {
            injector.rows[k].position = positions[k];
            injector.rows[k].velocity = injector.file.velocity;
            injector.rows[k].radius = radius.draw(injector.injection.seed, injector.firstId + k);
        }
        injector.rowsGiveSpin = injector.rowsGiveTemperature = injector.rowsGiveDensity = false;
        return;
    }
    }
}

} // namespace slides
