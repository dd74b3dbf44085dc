// FoamFile: one OpenFOAM data file (mesh or field) in memory, read token by token.
//
// Reference: OpenFOAM v1912 file format (User Guide "Input/output file format";
// src/OpenFOAM/db/IOstreams): a `FoamFile { format ascii|binary; arch "LSB;label=32;scalar=64";
// class ...; }` header, then entries. `path` or `path.gz` (zlib) is read whole. The header goes
// through the project's dictionary parser; big lists (`N ( ... )`, `N{v}`, and in binary format
// `N (` raw little-endian bytes `)`) are read by the fast readers here.
//
//     FoamFile { version 2.0; format binary; arch "LSB;label=32;scalar=64";
//                class volVectorField; object U; }
#pragma once

#include "slides/core/vector.h"

#include <cstdint>
#include <filesystem>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace slides {

class FoamFile {
public:
    /// Reads path, or path + ".gz" when only that exists; InputError if neither can be read,
    /// if both exist, or if the (inflated) file holds more than maxBytes, why says what bounds it.
    explicit FoamFile(const std::filesystem::path& path,
                      std::size_t maxBytes = std::numeric_limits<std::size_t>::max(),
                      const std::string& why = "");

    /// Whether path or path + ".gz" exists.
    static bool exists(const std::filesystem::path& path);

    const std::string& name() const { return name_; } ///< the file as read, for messages
    const std::string& className() const { return className_; }
    bool binary() const { return binary_; }

    bool atEnd();
    /// Next non-blank character without consuming it ('\0' at the end).
    char peek();
    void expect(char c);
    /// A word: letters, digits and _.:<>,-+ up to a blank or one of ;(){}[]".
    std::string word();
    /// A quoted string without its quotes.
    std::string quoted();
    long label();
    double scalar();
    Vec3 vector();
    /// A list `N ( ... )`, `N{value}` or `( ... )` of T (double, Vec3 or std::int64_t), in the
    /// file's format; an element count that differs from expected (when ≥ 0) is an error.
    template <typename T> std::vector<T> list(long expected = -1);
    /// An ASCII faceList `N ( n(a b c ...) ... )` or a faceCompactList (offsets then labels) as
    /// offsets (size N + 1) and the flat point labels.
    void faces(std::vector<std::int64_t>& offsets, std::vector<std::int64_t>& labels);
    /// Skips one entry's value up to and including its ';' (or a balanced { } block), binary
    /// lists included.
    void skipValue();

    /// Line of the current position (1-based).
    int line() const;
    [[noreturn]] void fail(const std::string& message) const;

private:
    void skipBlank();
    template <typename T> T element();
    template <typename T> T binaryElement();
    void readBinaryBytes(void* into, std::size_t bytes);

    std::string name_;
    std::string text_;
    std::size_t position_ = 0;
    std::string className_;
    bool binary_ = false;
    int labelBytes_ = 4;
    int scalarBytes_ = 8;
};

} // namespace slides
