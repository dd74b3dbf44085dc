// The declaration of every key of constant/slidesProperties: type, unit, default, allowed
// values and a doc line. This one table drives validation (unknown keys, types, ranges), the
// error texts and the README key table (`slides-track --list-keys`).
//
//     particles { density 5680; }   // declared as {"particles.density", scalar, "kg/m^3", ...}
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace slides {

enum class KeyKind {
    dictionary,
    scalar,
    integer,
    word,
    wordList,
    boolean,
    switchOrAuto, ///< a switch (on, off, yes, ...) or auto
    vector,
    integerTriple,
    timeRange ///< all, or (start end)
};

/// Range a number must lie in.
enum class KeyRange { any, positive, nonNegative, atLeastOne };

struct KeyDeclaration {
    std::string path; ///< dotted path; "*" stands for any one user-chosen name
    KeyKind kind;
    std::string unit;     ///< SI unit, "-" when dimensionless
    std::string fallback; ///< default as written in a dictionary; "" required; "-" optional
    std::vector<std::string> allowed; ///< allowed words (word keys only)
    KeyRange range = KeyRange::any;
    std::string doc;
    /// Bounds past any real case, where a run's arithmetic would overflow (in the README table).
    double minimum = -std::numeric_limits<double>::infinity();
    double maximum = std::numeric_limits<double>::infinity();

    bool required() const { return fallback.empty(); }
    bool optional() const { return fallback == "-"; }
};

/// The table, in README order.
const std::vector<KeyDeclaration>& sceneKeys();

/// The declaration whose path matches (with "*" wildcards), or nullptr.
const KeyDeclaration* findSceneKey(std::string_view path);

/// Whether a dotted path matches a declared pattern ("*" matches one component).
bool keyPathMatches(std::string_view pattern, std::string_view path);

/// The README table of keys (markdown).
std::string sceneKeysMarkdown();

} // namespace slides
