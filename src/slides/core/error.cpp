#include "slides/core/error.h"

#include <cstdio>

namespace slides {

namespace {

/// Length of the valid UTF-8 sequence at text[i], 0 if the bytes there are not one.
std::size_t utf8Length(const std::string& text, std::size_t i, char32_t& code) {
    const auto byte = [&](std::size_t k) { return static_cast<unsigned char>(text[k]); };
    const unsigned char lead = byte(i);
    const std::size_t length = lead >= 0xf0 && lead < 0xf5   ? 4
                               : lead >= 0xe0                ? 3
                               : lead >= 0xc2 && lead < 0xe0 ? 2
                                                             : 0;
    if (length == 0 || i + length > text.size()) return 0;
    code = lead & (0x7f >> length);
    for (std::size_t k = 1; k < length; ++k) {
        if ((byte(i + k) & 0xc0) != 0x80) return 0;
        code = (code << 6) | (byte(i + k) & 0x3f);
    }
    const bool overlong = (length == 3 && code < 0x800) || (length == 4 && code < 0x10000);
    const bool surrogate = code >= 0xd800 && code <= 0xdfff;
    return overlong || surrogate || code > 0x10ffff ? 0 : length;
}

/// Characters that print as nothing: byte-order mark, zero-width and direction marks.
bool invisible(char32_t code) {
    return code == 0xfeff || (code >= 0x200b && code <= 0x200f) ||
           (code >= 0x2028 && code <= 0x202e) || (code >= 0x2060 && code <= 0x2064) ||
           (code >= 0x80 && code < 0xa0);
}

/// text with control bytes, invalid UTF-8 and invisible characters escaped as \xNN or \uNNNN,
/// so a message shows every byte that made the input wrong (a NUL, a byte-order mark).
std::string printable(const std::string& text) {
    std::string shown;
    char escape[16];
    for (std::size_t i = 0; i < text.size();) {
        const auto c = static_cast<unsigned char>(text[i]);
        if (c >= 0x80) {
            char32_t code = 0;
            const std::size_t length = utf8Length(text, i, code);
            if (length > 0 && !invisible(code)) {
                shown.append(text, i, length);
            } else if (length > 0) {
                std::snprintf(escape, sizeof escape, "\\u%04X", static_cast<unsigned>(code));
                shown += escape;
            } else {
                std::snprintf(escape, sizeof escape, "\\x%02X", c);
                shown += escape;
            }
            i += length > 0 ? length : 1;
            continue;
        }
        if ((c < 0x20 && c != '\n' && c != '\t') || c == 0x7f) {
            std::snprintf(escape, sizeof escape, "\\x%02X", c);
            shown += escape;
        } else {
            shown += static_cast<char>(c);
        }
        ++i;
    }
    return shown;
}

std::string locate(const std::string& file, int line, const std::string& key,
                   const std::string& message) {
    std::string where = file.empty() ? std::string("input") : file;
    if (line > 0) where.append(":").append(std::to_string(line));
    if (!key.empty()) where.append(": key '").append(key).append("'");
    return printable(where.append(": ").append(message));
}

} // namespace

InputError::InputError(std::string file, int line, std::string key, const std::string& message)
    : std::runtime_error(locate(file, line, key, message)), file_(std::move(file)), line_(line),
      key_(std::move(key)), reason_(message) {}

} // namespace slides
