#include "slides/io/atomic_file.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <unistd.h>

namespace slides {

namespace {

std::filesystem::path temporaryFor(const std::filesystem::path& target) {
    return target.parent_path() /
           (target.filename().string() + ".tmp-" + std::to_string(::getpid()));
}

/// Flushes a written file to disk so the rename never publishes unwritten blocks.
void syncToDisk(const std::filesystem::path& file) {
    const int descriptor = ::open(file.c_str(), O_RDONLY);
    if (descriptor < 0 || ::fsync(descriptor) != 0) {
        const std::string reason = std::strerror(errno);
        if (descriptor >= 0) ::close(descriptor);
        throw OutputError("cannot write " + file.string() + ": " + reason);
    }
    ::close(descriptor);
}

} // namespace

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& writeTo) {
    const auto temporary = temporaryFor(target);
    try {
        writeTo(temporary);
        if (!std::filesystem::exists(temporary))
            throw OutputError("cannot write " + target.string() + ": nothing was written");
        syncToDisk(temporary);
        std::error_code error;
        std::filesystem::rename(temporary, target, error);
        if (error) throw OutputError("cannot write " + target.string() + ": " + error.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

void writeTextAtomically(const std::filesystem::path& target, std::string_view text) {
    writeFileAtomically(target, [&](const std::filesystem::path& temporary) {
        std::FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file)
            throw OutputError("cannot write " + target.string() + ": " + std::strerror(errno));
        const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
        const int savedErrno = errno;
        if (std::fclose(file) != 0 || !written)
            throw OutputError("cannot write " + target.string() + ": " +
                              std::strerror(written ? errno : savedErrno));
    });
}

} // namespace slides
