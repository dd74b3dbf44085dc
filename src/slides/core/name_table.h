// Name tables: each model family has one checked-in table of {value, name, ...} entries
// (dragModelNames(), integratorNames(), particleFieldNames()); these look it up either way.
#pragma once

#include <optional>
#include <stdexcept>
#include <string_view>

namespace slides {

/// The dictionary name of value in table; a value missing from its table is a logic error.
template <typename Table>
std::string_view nameOf(const Table& table, decltype(table[0].value) value) {
    for (const auto& entry : table)
        if (entry.value == value) return entry.name;
    throw std::logic_error("a value without an entry in its name table");
}

/// The value called name in table, if any.
template <typename Table>
std::optional<decltype(Table{}[0].value)> valueNamed(const Table& table, std::string_view name) {
    for (const auto& entry : table)
        if (entry.name == name) return entry.value;
    return std::nullopt;
}

} // namespace slides
