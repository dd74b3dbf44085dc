#include "slides/carrier/foam_file.h"

#include "slides/config/dictionary.h"
#include "slides/core/error.h"

#include <zlib.h>

#include <algorithm>
#include <charconv>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <sstream>

namespace slides {

namespace {

/// The bytes of path, at most maxBytes + 1 of them (one more tells that it is too long).
std::string readPlain(const std::filesystem::path& path, std::size_t maxBytes, bool& ok) {
    std::ifstream in(path, std::ios::binary);
    std::string text;
    char buffer[1 << 16];
    while (in && text.size() <= maxBytes) {
        in.read(buffer, sizeof buffer);
        text.append(buffer, static_cast<std::size_t>(in.gcount()));
    }
    ok = in.eof() || text.size() > maxBytes;
    return text;
}

/// The inflated bytes of path, at most maxBytes + 1 of them: a small file that inflates to
/// gigabytes is refused before it fills the memory.
std::string readCompressed(const std::filesystem::path& path, std::size_t maxBytes, bool& ok) {
    std::string text;
    gzFile in = gzopen(path.c_str(), "rb");
    ok = in != nullptr;
    if (!in) return text;
    char buffer[1 << 16];
    int count = 0;
    while (text.size() <= maxBytes && (count = gzread(in, buffer, sizeof buffer)) > 0)
        text.append(buffer, static_cast<std::size_t>(count));
    ok = count >= 0;
    gzclose(in);
    return text;
}

/// A blank: what std::isspace accepts in the C locale, without its call per character.
constexpr bool isBlank(char c) { return c == ' ' || (c >= '\t' && c <= '\r'); }

bool isDelimiter(char c) { return isBlank(c) || std::strchr(";(){}[]\"", c) != nullptr; }

} // namespace

bool FoamFile::exists(const std::filesystem::path& path) {
    return std::filesystem::is_regular_file(path) ||
           std::filesystem::is_regular_file(path.string() + ".gz");
}

FoamFile::FoamFile(const std::filesystem::path& path, std::size_t maxBytes, const std::string& why)
    : name_(path.string()) {
    const std::string compressed = name_ + ".gz";
    const bool plain = std::filesystem::is_regular_file(path);
    if (plain && std::filesystem::is_regular_file(compressed))
        throw InputError(name_, 0, "",
                         "both " + path.filename().string() + " and " + path.filename().string() +
                             ".gz exist: remove the one that is not the result");
    bool ok = false;
    if (plain) {
        text_ = readPlain(path, maxBytes, ok);
    } else if (std::filesystem::is_regular_file(compressed)) {
        name_ = compressed;
        text_ = readCompressed(name_, maxBytes, ok);
    } else {
        throw InputError(name_, 0, "", "missing file (nor " + name_ + ".gz)");
    }
    if (!ok) throw InputError(name_, 0, "", "cannot read the file");
    if (text_.size() > maxBytes)
        throw InputError(name_, 0, "",
                         std::string(plain ? "holds" : "inflates to") + " more than " +
                             std::to_string(maxBytes) + " bytes, " + why);

    // The header through the dictionary parser: FoamFile { ... } holds no nested braces.
    if (word() != "FoamFile") fail("expected the FoamFile { ... } header");
    const std::size_t close = text_.find('}', position_);
    if (close == std::string::npos) fail("unterminated FoamFile header");
    const auto headerText = "FoamFile " + text_.substr(position_, close + 1 - position_);
    const Dictionary file = Dictionary::parseString(headerText, name_);
    const Dictionary& header = *file.header();
    position_ = close + 1;
    className_ = header.has("class") ? header.word("class") : "";
    const std::string format = header.has("format") ? header.word("format") : "ascii";
    if (format != "ascii" && format != "binary") header.fail("format", "expected ascii or binary");
    binary_ = format == "binary";
    const std::string arch = header.has("arch") ? header.text("arch") : "LSB;label=32;scalar=64";
    if (binary_ && arch.find("LSB") == std::string::npos)
        header.fail("arch", "only little-endian (LSB) binary files can be read");
    if (arch.find("label=64") != std::string::npos) labelBytes_ = 8;
    if (arch.find("scalar=32") != std::string::npos) scalarBytes_ = 4;
}

int FoamFile::line() const {
    const auto end = text_.begin() + static_cast<std::ptrdiff_t>(std::min(position_, text_.size()));
    return 1 + static_cast<int>(std::count(text_.begin(), end, '\n'));
}

void FoamFile::fail(const std::string& message) const {
    throw InputError(name_, line(), "", message);
}

void FoamFile::skipBlank() {
    while (position_ < text_.size()) {
        const char c = text_[position_];
        if (isBlank(c)) {
            ++position_;
            continue;
        }
        const char next = position_ + 1 < text_.size() ? text_[position_ + 1] : '\0';
        if (c == '/' && next == '/') {
            position_ = text_.find('\n', position_);
            if (position_ == std::string::npos) position_ = text_.size();
        } else if (c == '/' && next == '*') {
            const std::size_t end = text_.find("*/", position_ + 2);
            position_ = end == std::string::npos ? text_.size() : end + 2;
        } else {
            return;
        }
    }
}

bool FoamFile::atEnd() {
    skipBlank();
    return position_ >= text_.size();
}

char FoamFile::peek() {
    skipBlank();
    return position_ < text_.size() ? text_[position_] : '\0';
}

void FoamFile::expect(char c) {
    const char found = peek();
    if (found != c) {
        std::string message = "expected '";
        message.push_back(c);
        message.append("', found ");
        if (found) {
            message.push_back('\'');
            message.push_back(found);
            message.push_back('\'');
        } else {
            message.append("the end of the file");
        }
        fail(message);
    }
    ++position_;
}

std::string FoamFile::word() {
    skipBlank();
    const std::size_t start = position_;
    while (position_ < text_.size() && !isDelimiter(text_[position_])) ++position_;
    if (position_ == start)
        fail(position_ < text_.size()
                 ? "expected a word, found '" + text_.substr(position_, 1) + "'"
                 : "expected a word, found the end of the file");
    return text_.substr(start, position_ - start);
}

std::string FoamFile::quoted() {
    expect('"');
    const std::size_t end = text_.find('"', position_);
    if (end == std::string::npos) fail("unterminated string");
    std::string text = text_.substr(position_, end - position_);
    position_ = end + 1;
    return text;
}

long FoamFile::label() {
    skipBlank();
    const char* start = text_.c_str() + position_;
    // std::from_chars reads no further than the number (strtol's checks may scan to the end of
    // the text: a whole faces list per label).
    long value = 0;
    const bool plus = *start == '+' && start[1] >= '0' && start[1] <= '9';
    const char* digits = plus ? start + 1 : start; // from_chars takes no '+'
    const auto [end, error] = std::from_chars(digits, text_.c_str() + text_.size(), value);
    if (error != std::errc() || end == digits || (*end && !isDelimiter(*end)))
        fail("bad token '" +
             text_.substr(position_, std::min<std::size_t>(20, text_.size() - position_)) +
             "': expected an integer");
    position_ += static_cast<std::size_t>(end - start);
    return value;
}

double FoamFile::scalar() {
    skipBlank();
    const char* start = text_.c_str() + position_;
    // std::from_chars rounds correctly, as strtod does, in a fraction of its time (ASCII fields
    // of a time series); strtod reads what it leaves (a '+' sign, hexadecimal, out of range).
    double value = 0;
    const auto [parsed, error] = std::from_chars(start, text_.c_str() + text_.size(), value);
    const char* end = parsed;
    if (error != std::errc() || end == start || (*end && !isDelimiter(*end))) {
        char* strtodEnd = nullptr;
        value = std::strtod(start, &strtodEnd);
        end = strtodEnd;
    }
    if (end == start || (*end && !isDelimiter(*end)))
        fail("bad token '" +
             text_.substr(position_, std::min<std::size_t>(20, text_.size() - position_)) +
             "': expected a number");
    position_ += static_cast<std::size_t>(end - start);
    return value;
}

Vec3 FoamFile::vector() {
    expect('(');
    Vec3 value;
    for (int axis = 0; axis < 3; ++axis) value[axis] = scalar();
    expect(')');
    return value;
}

template <> double FoamFile::element<double>() { return scalar(); }
template <> Vec3 FoamFile::element<Vec3>() { return vector(); }
template <> std::int64_t FoamFile::element<std::int64_t>() { return label(); }

void FoamFile::readBinaryBytes(void* into, std::size_t bytes) {
    if (position_ + bytes > text_.size()) fail("binary list runs past the end of the file");
    std::memcpy(into, text_.data() + position_, bytes);
    position_ += bytes;
}

template <> double FoamFile::binaryElement<double>() {
    if (scalarBytes_ == 4) {
        float value = 0;
        readBinaryBytes(&value, sizeof value);
        return value;
    }
    double value = 0;
    readBinaryBytes(&value, sizeof value);
    return value;
}

template <> Vec3 FoamFile::binaryElement<Vec3>() {
    Vec3 value;
    for (int axis = 0; axis < 3; ++axis) value[axis] = binaryElement<double>();
    return value;
}

template <> std::int64_t FoamFile::binaryElement<std::int64_t>() {
    if (labelBytes_ == 4) {
        std::int32_t value = 0;
        readBinaryBytes(&value, sizeof value);
        return value;
    }
    std::int64_t value = 0;
    readBinaryBytes(&value, sizeof value);
    return value;
}

template <typename T> std::vector<T> FoamFile::list(long expected) {
    std::vector<T> values;
    long count = -1;
    if (peek() != '(') {
        count = label();
        if (count < 0) fail("negative list size " + std::to_string(count));
        if (expected >= 0 && count != expected)
            fail("list of " + std::to_string(count) + " values, expected " +
                 std::to_string(expected) + " (size mismatch with the mesh)");
        if (peek() == '{') { // N{value}: every element the same
            ++position_;
            const T value = element<T>();
            expect('}');
            return std::vector<T>(static_cast<std::size_t>(count), value);
        }
    }
    expect('(');
    if (binary_ && count >= 0) {
        values.reserve(static_cast<std::size_t>(count));
        for (long i = 0; i < count; ++i) values.push_back(binaryElement<T>());
    } else {
        if (count >= 0) values.reserve(static_cast<std::size_t>(count));
        while (peek() != ')') {
            if (atEnd()) fail("unterminated list");
            values.push_back(element<T>());
        }
        if (count >= 0 && static_cast<long>(values.size()) != count)
            fail("list announced " + std::to_string(count) + " values but holds " +
                 std::to_string(values.size()));
    }
    expect(')');
    if (expected >= 0 && static_cast<long>(values.size()) != expected)
        fail("list of " + std::to_string(values.size()) + " values, expected " +
             std::to_string(expected) + " (size mismatch with the mesh)");
    return values;
}

template std::vector<double> FoamFile::list<double>(long);
template std::vector<Vec3> FoamFile::list<Vec3>(long);
template std::vector<std::int64_t> FoamFile::list<std::int64_t>(long);

void FoamFile::faces(std::vector<std::int64_t>& offsets, std::vector<std::int64_t>& labels) {
    if (className_ == "faceCompactList") {
        offsets = list<std::int64_t>();
        labels = list<std::int64_t>();
        if (offsets.empty() || offsets.back() != static_cast<std::int64_t>(labels.size()))
            fail("face offsets do not match the point labels");
        return;
    }
    const long count = label();
    offsets.assign(1, 0);
    offsets.reserve(static_cast<std::size_t>(count) + 1);
    labels.clear();
    expect('(');
    for (long face = 0; face < count; ++face) {
        const auto points = list<std::int64_t>();
        labels.insert(labels.end(), points.begin(), points.end());
        offsets.push_back(static_cast<std::int64_t>(labels.size()));
    }
    expect(')');
}

void FoamFile::skipValue() {
    int depth = 0;
    std::string previous;
    while (!atEnd()) {
        const char c = text_[position_];
        if (c == ';') { // ends the entry, or an entry of a sub-dictionary inside it
            ++position_;
            if (depth == 0) return;
            previous.clear();
            continue;
        }
        if (c == '{' || c == '(' || c == '[') {
            ++depth;
            ++position_;
        } else if (c == '}' || c == ')' || c == ']') {
            --depth;
            ++position_;
            if (depth == 0 && c == '}') return;
            if (depth < 0) fail(std::string("unbalanced '") + c + "'");
        } else if (c == '"') {
            const std::size_t end = text_.find('"', position_ + 1);
            if (end == std::string::npos) fail("unterminated string");
            position_ = end + 1;
        } else {
            const std::string token = word();
            // A binary List<T> N ( raw bytes ): skip by reading it.
            if (binary_ && previous.rfind("List<", 0) == 0 && peek() == '(' &&
                std::isdigit(static_cast<unsigned char>(token[0]))) {
                position_ -= token.size();
                if (previous == "List<vector>")
                    list<Vec3>();
                else if (previous == "List<scalar>")
                    list<double>();
                else
                    fail("cannot skip a binary " + previous);
                previous.clear();
                continue;
            }
            previous = token;
        }
    }
    fail("unterminated entry");
}

} // namespace slides
