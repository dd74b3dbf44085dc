// Running the command line on cases in tests: the default case, scratch directories and files.
#pragma once

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

namespace slides::test {

inline const std::filesystem::path sourceDir = SLIDES_SOURCE_DIR;
inline const std::filesystem::path defaultCase = sourceDir / "foamCases" / "analyticSpray";

inline std::string slurp(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

/// A scratch directory with an empty constant/, removed at the end of the test.
struct ScratchDirectory {
    std::filesystem::path path;
    explicit ScratchDirectory(const std::string& name)
        : path(std::filesystem::temp_directory_path() /
               ("slides-" + name + "-" + std::to_string(::getpid()))) {
        std::filesystem::remove_all(path);
        std::filesystem::create_directories(path / "constant");
    }
    ~ScratchDirectory() { std::filesystem::remove_all(path); }
};

/// Runs `slides-track arguments`, output to log; returns the exit status (−1: killed).
inline int runCli(const std::string& arguments, const std::filesystem::path& log) {
    const std::string command =
        std::string(SLIDES_TRACK_EXE) + " " + arguments + " > " + log.string() + " 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace slides::test
