#include "slides/core/error.h"

namespace slides {

namespace {
std::string locate(const std::string& file, int line, const std::string& key,
                   const std::string& message) {
    std::string where = file.empty() ? std::string("input") : file;
    if (line > 0) where.append(":").append(std::to_string(line));
    if (!key.empty()) where.append(": key '").append(key).append("'");
    return where.append(": ").append(message);
}
} // namespace

InputError::InputError(std::string file, int line, std::string key, const std::string& message)
    : std::runtime_error(locate(file, line, key, message)), file_(std::move(file)), line_(line),
      key_(std::move(key)), reason_(message) {}

} // namespace slides
