// Atomic file writes: write under a temporary name in the same directory, flush to disk,
// rename over the target. A crash or a full disk never leaves a truncated file that looks
// complete; the previous version, if any, stays intact until the new one is whole.
#pragma once

#include <filesystem>
#include <functional>
#include <stdexcept>
#include <string_view>

namespace slides {

/// A file could not be written; the message names the file and the reason.
class OutputError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// Creates the temporary `<target>.tmp-<pid>` (empty), calls writeTo(temporary) to fill it,
/// flushes it to disk and renames it to target. If anything fails or writeTo throws, the
/// temporary is removed, target is untouched and the exception propagates (OutputError for
/// failures here).
void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& writeTo);

void writeTextAtomically(const std::filesystem::path& target, std::string_view text);

/// Removes the temporaries `<name>.tmp-<pid>` in directory whose process is no longer running
/// (a run killed while writing); those of running processes stay.
void removeStaleTemporaries(const std::filesystem::path& directory);

} // namespace slides
