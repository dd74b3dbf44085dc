// Running the command line on cases in tests: the default case, scratch directories and files.
#pragma once

#include <cctype>
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

/// Copies a solved OpenFOAM run (SLIDES_FOAM_RUNS_DIR/<run>) to directory: its constant/ and
/// its time directories after 0.
inline void copySolvedRun(const std::string& run, const std::filesystem::path& directory) {
    namespace fs = std::filesystem;
    const fs::path solved = fs::path(SLIDES_FOAM_RUNS_DIR) / run;
    fs::copy(solved / "constant", directory / "constant",
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    for (const auto& entry : fs::directory_iterator(solved)) {
        const std::string name = entry.path().filename().string();
        if (entry.is_directory() && std::isdigit(static_cast<unsigned char>(name[0])) &&
            name != "0")
            fs::copy(entry.path(), directory / name, fs::copy_options::recursive);
    }
}

/// Runs `slides-track arguments`, output to log; returns the exit status (−1: killed).
inline int runCli(const std::string& arguments, const std::filesystem::path& log) {
    const std::string command =
        std::string(SLIDES_TRACK_EXE) + " " + arguments + " > " + log.string() + " 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

} // namespace slides::test
