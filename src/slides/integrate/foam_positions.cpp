#include "slides/integrate/foam_positions.h"

#include "slides/carrier/foam_file.h"
#include "slides/core/error.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

namespace slides {

namespace {

/// One entry: (x y z), then up to three labels, which are skipped.
Vec3 readEntry(FoamFile& file, std::size_t entry) {
    const std::string which = "entry " + std::to_string(entry + 1) + ": ";
    if (file.peek() != '(') file.fail(which + "expected a position (x y z)");
    file.expect('(');
    std::vector<double> coordinates;
    while (file.peek() != ')' && !file.atEnd()) {
        const std::string token = file.word();
        char* end = nullptr;
        coordinates.push_back(std::strtod(token.c_str(), &end));
        if (end != token.c_str() + token.size() || !std::isfinite(coordinates.back()))
            file.fail(which + "expected a number, found '" + token + "'");
    }
    file.expect(')');
    if (coordinates.size() != 3)
        file.fail(which + "a position has 3 coordinates, this has " +
                  std::to_string(coordinates.size()) +
                  " (barycentric coordinates are not read: give Cartesian positions)");
    const auto startsLabel = [](char c) {
        return std::isdigit(static_cast<unsigned char>(c)) || c == '-' || c == '+';
    };
    for (int labels = 0; labels < 3 && startsLabel(file.peek()); ++labels) file.label();
    return {coordinates[0], coordinates[1], coordinates[2]};
}

std::vector<Vec3> readPositions(FoamFile& file) {
    if (file.binary()) return file.list<Vec3>();
    long announced = -1;
    int announcedAt = 0;
    if (file.peek() != '(') {
        announcedAt = file.line();
        announced = file.label();
        if (announced < 0) file.fail("negative list length " + std::to_string(announced));
    }
    file.expect('(');
    std::vector<Vec3> positions;
    while (file.peek() != ')') {
        if (file.atEnd()) file.fail("unterminated list: no ')' after the last position");
        positions.push_back(readEntry(file, positions.size()));
    }
    file.expect(')');
    if (announced >= 0 && static_cast<std::size_t>(announced) != positions.size())
        throw InputError(file.name(), announcedAt, "",
                         "the list announces " + std::to_string(announced) +
                             " positions and holds " + std::to_string(positions.size()));
    return positions;
}

} // namespace

std::vector<Vec3> readFoamPositions(const std::filesystem::path& path, const std::string& key) {
    try {
        FoamFile file(path);
        std::vector<Vec3> positions = readPositions(file);
        if (!file.atEnd()) file.fail("unexpected text after the list");
        if (positions.empty()) file.fail("no positions in the list");
        return positions;
    } catch (const InputError& error) { // the file's place, with the key that names the file
        throw InputError(error.file(), error.line(), key, error.reason());
    }
}

} // namespace slides
