#include "slides/io/atomic_file.h"

#include <cerrno>
#include <charconv>
#include <cstdio>
#include <cstring>
#include <string>
#include <system_error>

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

namespace slides {

namespace {

[[noreturn]] void fail(const std::filesystem::path& target, const std::string& reason) {
    throw OutputError("cannot write " + target.string() + ": " + reason);
}

/// Opens file with flags, then closes it; fsync first when asked. Throws with errno's reason.
void openAndClose(const std::filesystem::path& target, const std::filesystem::path& file, int flags,
                  bool sync) {
    const int descriptor = ::open(file.c_str(), flags | O_CLOEXEC, 0666);
    if (descriptor < 0) fail(target, std::strerror(errno));
    const bool synced = !sync || ::fsync(descriptor) == 0;
    const int syncErrno = errno;
    if (::close(descriptor) != 0 || !synced)
        fail(target, std::strerror(synced ? errno : syncErrno));
}

} // namespace

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(const std::filesystem::path&)>& writeTo) {
    const auto temporary =
        target.parent_path() / (target.filename().string() + ".tmp-" + std::to_string(::getpid()));
    // Creating the temporary here reports a missing or read-only directory with the OS reason,
    // before a writer such as VTK's can fail with a vaguer one.
    openAndClose(target, temporary, O_WRONLY | O_CREAT | O_TRUNC, false);
    try {
        writeTo(temporary);
        // Flushed before the rename, so the target never names unwritten blocks.
        openAndClose(target, temporary, O_RDONLY, true);
        std::error_code error;
        std::filesystem::rename(temporary, target, error);
        if (error) fail(target, error.message());
    } catch (...) {
        std::error_code ignored;
        std::filesystem::remove(temporary, ignored);
        throw;
    }
}

void writeTextAtomically(const std::filesystem::path& target, std::string_view text) {
    writeFileAtomically(target, [&](const std::filesystem::path& temporary) {
        std::FILE* file = std::fopen(temporary.c_str(), "wb");
        if (!file) fail(target, std::strerror(errno));
        const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
        const int writeErrno = errno;
        if (std::fclose(file) != 0 || !written)
            fail(target, std::strerror(written ? errno : writeErrno));
    });
}

void removeStaleTemporaries(const std::filesystem::path& directory) {
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(directory, error)) {
        const std::string name = entry.path().filename().string();
        const auto marker = name.rfind(".tmp-");
        if (marker == std::string::npos) continue;
        const char* digits = name.data() + marker + 5;
        const char* end = name.data() + name.size();
        pid_t pid = 0;
        const auto parsed = std::from_chars(digits, end, pid);
        if (parsed.ec != std::errc() || parsed.ptr != end || pid <= 0) continue;
        // kill(pid, 0) fails with ESRCH exactly when no process has that id.
        if (pid != ::getpid() && ::kill(pid, 0) != 0 && errno == ESRCH)
            std::filesystem::remove(entry.path(), error);
    }
}

} // namespace slides
