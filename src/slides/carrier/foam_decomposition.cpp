#include "slides/carrier/foam_decomposition.h"

#include "slides/carrier/foam_field.h"
#include "slides/carrier/foam_file.h"
#include "slides/core/error.h"

#include <cstdlib>
#include <set>

namespace slides {

namespace {

/// The numeric directory names of dir (OpenFOAM's time directories).
std::set<std::string> timeDirectories(const std::filesystem::path& dir) {
    std::set<std::string> times;
    std::error_code error;
    for (const auto& entry : std::filesystem::directory_iterator(dir, error)) {
        if (!entry.is_directory()) continue;
        const std::string name = entry.path().filename().string();
        char* end = nullptr;
        std::strtod(name.c_str(), &end);
        if (end != name.c_str() && *end == 0) times.insert(name);
    }
    return times;
}

std::string listed(const std::set<std::string>& names) {
    std::string text;
    for (const auto& name : names) text += (text.empty() ? "" : " ") + name;
    return text.empty() ? "none" : text;
}

} // namespace

std::filesystem::path foamProcessorDirectory(const std::filesystem::path& caseDirectory, int rank) {
    return caseDirectory / ("processor" + std::to_string(rank));
}

int foamProcessorCount(const std::filesystem::path& caseDirectory) {
    int count = 0;
    while (std::filesystem::is_directory(foamProcessorDirectory(caseDirectory, count))) ++count;
    return count;
}

void requireDecompositionFits(const std::filesystem::path& caseDirectory, bool parallel,
                              int ranks) {
    const int parts = foamProcessorCount(caseDirectory);
    const std::string where = caseDirectory.string();
    if (!parallel) {
        if (parts == 0) return;
        const std::string advice = "run `mpirun -np " + std::to_string(parts) + " slides-track " +
                                   where + " -parallel`, or `reconstructPar`";
        if (!FoamFile::exists(caseDirectory / "constant" / "polyMesh" / "boundary"))
            throw InputError(where, 0, "",
                             "the case is decomposed into " + std::to_string(parts) +
                                 " processor folders and has no whole mesh: " + advice);
        std::filesystem::path whole;
        try {
            whole = foamTimeDirectory(caseDirectory, "latestTime").filename();
        } catch (const InputError&) {
            throw InputError(where, 0, "",
                             "the case is decomposed into " + std::to_string(parts) +
                                 " processor folders and no time directory of the whole case "
                                 "holds a field U: " +
                                 advice);
        }
        const auto part =
            foamTimeDirectory(foamProcessorDirectory(caseDirectory, 0), "latestTime").filename();
        if (std::strtod(part.c_str(), nullptr) > std::strtod(whole.c_str(), nullptr))
            throw InputError(where, 0, "",
                             "the processor folders hold a later solution (time " + part.string() +
                                 ") than the whole case (" + whole.string() + "): " + advice);
        return;
    }
    if (parts == 0)
        throw InputError(where, 0, "",
                         "-parallel needs a decomposed case (processor0, processor1, ...): run "
                         "`decomposePar` first, or run without -parallel");
    if (parts != ranks)
        throw InputError(where, 0, "",
                         "the case is decomposed into " + std::to_string(parts) +
                             " processor folders but the run has " + std::to_string(ranks) +
                             " ranks: run `mpirun -np " + std::to_string(parts) +
                             " ... -parallel`");
    const auto first = timeDirectories(foamProcessorDirectory(caseDirectory, 0));
    for (int rank = 1; rank < parts; ++rank) {
        const auto dir = foamProcessorDirectory(caseDirectory, rank);
        if (const auto times = timeDirectories(dir); times != first)
            throw InputError(dir.string(), 0, "",
                             "holds time directories " + listed(times) + " but processor0 holds " +
                                 listed(first) + ": decompose every time alike (decomposePar)");
    }
}

} // namespace slides
