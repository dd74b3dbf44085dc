// CSV table: a numeric table whose header names its columns, for files that give particles or
// sizes row by row (integrate/particle_file.h, integrate/size_distribution.h).
//
//     x,y,z,u,v,w,d        (commas or spaces; `#` starts a comment line)
//     0.001,0,0,12,0,0,1e-4
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace slides {

struct CsvTable {
    std::filesystem::path file;
    std::vector<std::string> columns; ///< as named by the header
    std::vector<std::vector<double>> rows;
    std::vector<int> lines; ///< the file's line of each row

    /// The index of the named column, if the header has it.
    std::optional<std::size_t> column(const std::string& name) const;
    /// Throws InputError naming file:line of row (0: the header) and key.
    [[noreturn]] void fail(std::size_t row, const std::string& key,
                           const std::string& message) const;
};

/// Reads the table; every header name must be one of known (none twice), every value a finite
/// number, and there must be at least one row.
CsvTable readCsvTable(const std::filesystem::path& file, const std::vector<std::string>& known);

} // namespace slides
