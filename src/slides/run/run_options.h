// Run options: what the command line asks of one run (src/app/main.cpp fills them).
//
//     slides-track CASE --output DIR --end-time 0.01 --dt 1e-5 --threads 2 --checkpoint-every 500
//     slides-track CASE --check
#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace slides {

/// Command-line overrides of the dictionary, checked like dictionary values.
struct SceneOverrides {
    std::optional<double> endTime;   ///< --end-time [s], overrides time.endTime
    std::optional<double> dt;        ///< --dt [s], overrides time.dt
    std::optional<std::string> time; ///< --time, overrides foamFieldCoeffs.time
};

struct RunOptions {
    std::filesystem::path caseDirectory;
    std::filesystem::path output; ///< empty: CASE/slides
    SceneOverrides overrides;
    int threads = 0;          ///< 0: all cores
    long checkpointEvery = 0; ///< steps between checkpoints; 0: none
    bool restart = false;     ///< continue from OUTPUT/checkpoint.h5
    bool quiet = false;       ///< no progress display or report
    bool parallel = false;    ///< -parallel: the case's processor*/ parts, one a rank (MPI)
    bool check = false;       ///< read and resolve the case, print the decisions, write nothing
};

} // namespace slides
