#include "slides/integrate/csv_table.h"

#include "slides/core/error.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>

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

} // namespace

std::optional<std::size_t> CsvTable::column(const std::string& name) const {
    const auto at = std::find(columns.begin(), columns.end(), name);
    if (at == columns.end()) return std::nullopt;
    return static_cast<std::size_t>(at - columns.begin());
}

void CsvTable::fail(std::size_t row, const std::string& key, const std::string& message) const {
    const int line = row < lines.size() ? lines[row] : 0;
    throw InputError(file.string(), line, key, message);
}

CsvTable readCsvTable(const std::filesystem::path& file, const std::vector<std::string>& known) {
    std::ifstream in(file);
    if (!in) throw InputError(file.string(), 0, "", "cannot read the file");
    CsvTable table;
    table.file = file;
    std::string line, names;
    for (const auto& name : known) names += " " + name;
    int lineNumber = 0, headerLine = 0;
    const auto fail = [&](const std::string& key, const std::string& message) {
        throw InputError(file.string(), lineNumber, key, message);
    };
    while (std::getline(in, line)) {
        ++lineNumber;
        const auto fields = fieldsOf(line);
        if (fields.empty() || fields[0].starts_with('#')) continue;
        if (table.columns.empty()) { // the header
            for (const auto& field : fields) {
                if (std::find(known.begin(), known.end(), field) == known.end())
                    fail(field, "unknown column; columns are" + names);
                if (table.column(field)) fail(field, "column given twice");
                table.columns.push_back(field);
            }
            headerLine = lineNumber;
            continue;
        }
        if (fields.size() != table.columns.size())
            fail("", std::to_string(fields.size()) + " values, the header names " +
                         std::to_string(table.columns.size()) + " columns");
        std::vector<double> values(fields.size());
        for (std::size_t c = 0; c < fields.size(); ++c) {
            const std::string& text = fields[c];
            const auto [end, error] =
                std::from_chars(text.data(), text.data() + text.size(), values[c]);
            if (error != std::errc() || end != text.data() + text.size() ||
                !std::isfinite(values[c]))
                fail(table.columns[c], "expected a finite number, found '" + text + "'");
        }
        table.rows.push_back(std::move(values));
        table.lines.push_back(lineNumber);
    }
    lineNumber = headerLine;
    if (table.rows.empty()) fail("", "no rows");
    return table;
}

} // namespace slides
