// Dictionary: reads OpenFOAM-syntax dictionaries such as constant/slidesProperties.
//
// Reference: OpenFOAM v1912 dictionary syntax (OpenFOAM User Guide, "Input/output file format",
// and src/OpenFOAM/db/dictionary): `keyword value;` entries, `keyword { ... }` sub-dictionaries,
// lists `( )`, `N( )`, `N{v}`, dimension sets `[ ]`, comments, `$macros` and `#include`.
// Duplicate keywords follow OpenFOAM's default `#inputMode merge`: a later value replaces the
// earlier one in place, and a later sub-dictionary is merged into an earlier one.
//
//     FoamFile { version 2.0; format ascii; class dictionary; object slidesProperties; }
//     standoff    0.06;                               // [m]
//     fluid       { density [1 -3 0 0 0 0 0] 1.1; }
//     surfaces    { target { point ($:standoff 0 0); normal (-1 0 0); } }
#pragma once

#include <Eigen/Core>

#include <filesystem>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace slides {

class Dictionary;

/// The exponents of an OpenFOAM dimension set [kg m s K mol A cd] (7 or 5 of them).
struct DimensionSet {
    std::vector<double> exponents;
};

/// One value item of an entry: a number, word, quoted string, list or dictionary.
class DictItem {
public:
    enum class Kind { number, word, string, list, dictionary };

    static DictItem makeNumber(double value, bool writtenAsInteger, int line);
    static DictItem makeWord(std::string word, int line);
    static DictItem makeString(std::string text, int line);
    static DictItem makeList(std::vector<DictItem> elements, int line);
    static DictItem makeDictionary(std::shared_ptr<const Dictionary> dictionary, int line);

    Kind kind() const { return kind_; }
    int line() const { return line_; }
    bool isNumber() const { return kind_ == Kind::number; }
    bool isWord() const { return kind_ == Kind::word; }
    bool isString() const { return kind_ == Kind::string; }
    bool isList() const { return kind_ == Kind::list; }
    bool isDictionary() const { return kind_ == Kind::dictionary; }

    /// Number value; writtenAsInteger() tells whether it was spelled without '.' or exponent.
    double number() const;
    bool writtenAsInteger() const { return kind_ == Kind::number && integer_; }
    /// Text of a word or (unquoted, unescaped) string.
    const std::string& text() const;
    const std::vector<DictItem>& list() const;
    const Dictionary& dictionary() const;

    /// For messages: "number 2.5", "word 'fast'", "string \"a b\"", "a list of 3 items", ...
    std::string describe() const;

private:
    friend class DictionaryParser;

    DictItem(Kind kind, int line) : kind_(kind), line_(line) {}

    Kind kind_;
    int line_;
    double number_ = 0;
    bool integer_ = false;
    std::string text_;
    std::vector<DictItem> list_;
    std::shared_ptr<const Dictionary> dictionary_;
};

/// One `keyword items... ;` entry, or a `keyword { ... }` sub-dictionary entry.
struct DictEntry {
    std::string keyword;
    int line = 0;
    std::string file;            ///< where the entry was written (an #include'd file, maybe)
    std::vector<DictItem> items; ///< values, dimension set excluded; empty for a sub-dictionary
    std::optional<DimensionSet> dimensions;
    std::shared_ptr<const Dictionary> dictionary; ///< set for a sub-dictionary entry

    bool isDict() const { return dictionary != nullptr; }
};

/// A parsed dictionary: ordered entries, typed reads, and errors located at file, line and key.
class Dictionary {
public:
    /// Throws InputError (line 0 when the file is missing or unreadable).
    static Dictionary parseFile(const std::filesystem::path& file);
    /// fileName is used in errors; #include paths are relative to its directory.
    static Dictionary parseString(std::string_view text, std::string fileName);

    const std::string& file() const { return file_; }
    /// Dotted path from the top, "" for the top level, e.g. "carrier.analyticJetCoeffs".
    const std::string& path() const { return path_; }
    /// path() + "." + key, or key at the top level (path() when key is empty).
    std::string keyPath(std::string_view key) const;
    /// Line of the opening '{' (0 for the top level).
    int line() const { return line_; }
    /// The FoamFile { ... } header, nullptr if the file has none.
    const Dictionary* header() const { return header_.get(); }

    /// Whether a $reference read the entry at keyPath (top-level dictionary only): such an
    /// entry is a variable of the file, like `standoff 0.06;` used as `$:standoff`.
    bool isReferenced(std::string_view keyPath) const;

    /// Keywords in order of first appearance, FoamFile header excluded.
    std::vector<std::string> keys() const;
    const std::vector<DictEntry>& entries() const { return entries_; }
    bool has(std::string_view key) const { return find(key) != nullptr; }
    const DictEntry* find(std::string_view key) const;
    /// Line of the entry, 0 if absent.
    int lineOf(std::string_view key) const;
    bool isDict(std::string_view key) const;
    const Dictionary& subDict(std::string_view key) const;

    // Typed reads: exactly one item of the right kind, else an InputError at the key that says
    // what was expected and what was found. A missing key is an error at the dictionary's line.
    double scalar(std::string_view key) const;
    long integer(std::string_view key) const;     ///< a whole number
    std::string word(std::string_view key) const; ///< a word, or a quoted string without spaces
    std::string text(std::string_view key) const; ///< a word or any quoted string
    bool boolean(std::string_view key) const;     ///< on/off, true/false, yes/no
    Eigen::Vector3d vector(std::string_view key) const; ///< (x y z)
    std::vector<double> scalarList(std::string_view key) const;
    std::vector<std::string> wordList(std::string_view key) const;

    /// Throws an InputError located at the key (at the dictionary when the key is absent).
    [[noreturn]] void fail(std::string_view key, const std::string& message) const;

private:
    friend class DictionaryParser;

    Dictionary(std::string file, std::string path, int line)
        : file_(std::move(file)), path_(std::move(path)), line_(line) {}

    const DictEntry& required(std::string_view key) const;
    const DictItem& singleItem(std::string_view key, const std::string& expected) const;
    /// Throws an InputError at an existing key, on the given line (of the entry or one item).
    [[noreturn]] void failAt(std::string_view key, int line, const std::string& message) const;

    std::string file_;
    std::string path_;
    int line_ = 0;
    std::vector<DictEntry> entries_;
    std::shared_ptr<const Dictionary> header_;
    std::set<std::string> referencedKeyPaths_; ///< top level: entries read by a $reference
};

} // namespace slides
