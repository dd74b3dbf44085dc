// slides-track: track particles through a carrier-gas field and write the results for ParaView.
//
//     slides-track foamCases/analyticSpray            # results in foamCases/analyticSpray/slides/
//     slides-track CASE --output DIR --dt 1e-5 --threads 2
//     slides-track foamCases/impingingJet --time 500     # an OpenFOAM case, its time 500
//     slides-track CASE --checkpoint-every 500     # after a crash: slides-track CASE --restart
//     mpirun -np 4 slides-track CASE -parallel     # a decomposed case, one rank a processor*/
//     slides-track CASE --check                    # read, analyse, print the decisions only
//     slides-track --init CASE                     # write a commented
//     CASE/constant/slidesProperties
// Exit status: 0 success, 2 bad input (one message naming file, line and key), 1 a run stopped
// at a non-finite particle state or an internal error.
#include "slides/config/case_template.h"
#include "slides/config/scene_keys.h"
#include "slides/core/error.h"
#include "slides/core/thread_waits.h"
#include "slides/io/atomic_file.h"
#include "slides/run/rank_agreement.h"
#include "slides/run/run_case.h"

#include <CLI/CLI.hpp>

#include <cstdio>
#include <iostream>
#include <optional>
#include <string_view>

int main(int argc, char** argv) {
    slides::sleepWhileWaitingForWork(argv);
    // OpenFOAM's single-dash -parallel: MPI starts only then, so serial runs need no mpirun.
    bool parallel = false;
    for (int a = 1; a < argc; ++a)
        if (std::string_view(argv[a]) == "-parallel" || std::string_view(argv[a]) == "--parallel") {
            argv[a] = const_cast<char*>("--parallel");
            parallel = true;
        }
    std::optional<slides::MpiSession> mpi;
    if (parallel) mpi.emplace(argc, argv);
    const slides::RankCommunicator ranks =
        parallel ? slides::RankCommunicator::world() : slides::RankCommunicator{};
    CLI::App app{"slides-track: Lagrangian particle tracking in a carrier-gas jet.\n"
                 "CASE holds constant/slidesProperties; results go to CASE/slides/."};
    slides::RunOptions options;
    bool listKeys = false;
    bool init = false;
    app.add_option("CASE", options.caseDirectory, "case directory")->check(CLI::ExistingDirectory);
    app.add_option("--output", options.output, "output directory (default CASE/slides)");
    app.add_option("--end-time", options.overrides.endTime, "end time [s], overrides time.endTime");
    app.add_option("--dt", options.overrides.dt, "time step [s], overrides time.dt");
    app.add_option(
        "--time", options.overrides.time,
        "OpenFOAM time directory (latestTime or a value), overrides foamFieldCoeffs.time");
    app.add_option("--threads", options.threads, "threads (default: all cores)")
        ->check(CLI::Range(1, 4096).description("a whole number from 1 to 4096"));
    app.add_option("--checkpoint-every", options.checkpointEvery,
                   "write OUTPUT/checkpoint.h5 every N steps (whole state, atomically)")
        ->check(CLI::Range(1L, 1000000000L).description("a whole number of steps ≥ 1"));
    app.add_flag("--restart", options.restart,
                 "continue from OUTPUT/checkpoint.h5; results identical to an uninterrupted run");
    app.add_flag("--quiet", options.quiet, "no progress display or report");
    app.add_flag("--parallel", options.parallel,
                 "-parallel under mpirun: the case's processor*/ decomposition, one part a rank");
    app.add_flag("--check", options.check,
                 "read the case and run the scene analysis, print its decisions; write nothing");
    app.add_flag("--init", init,
                 "write a commented CASE/constant/slidesProperties for the case (its mesh, "
                 "patches and inlet) that runs as written; never overwrites one");
    app.add_flag("--list-keys", listKeys,
                 "print the table of slidesProperties keys (markdown) and exit");
    app.set_version_flag("--version", std::string("slides-track ") + SLIDES_VERSION);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int status = app.exit(error);
        return status == 0 ? 0 : 2;
    }
    if (listKeys) {
        std::cout << slides::sceneKeysMarkdown();
        return 0;
    }
    if (options.caseDirectory.empty()) {
        std::cerr << "slides-track: error: no CASE directory given (see --help)\n";
        return 2;
    }
    // In parallel, an error every rank agreed on is printed once (by rank 0) and every rank
    // returns; one found by a rank alone ends the whole job through MPI_Abort with its status.
    const auto fail = [&](const std::exception& error, const char* kind, int status) {
        const bool agreed = dynamic_cast<const slides::AgreedError*>(&error) != nullptr;
        if (!agreed || ranks.rank() == 0)
            std::fprintf(stderr, "\nslides-track: %s: %s\n", kind, error.what());
        if (ranks.parallel() && !agreed) {
            std::fflush(stderr);
            ranks.abort(status);
        }
        return status;
    };
    try {
        if (init) {
            const auto written = slides::writeCaseTemplate(options.caseDirectory);
            std::cout << "wrote " << written.string() << "\n";
            return 0;
        }
        slides::runCase(options, ranks);
        return 0;
    } catch (const slides::InputError& error) {
        return fail(error, "error", 2);
    } catch (const slides::OutputError& error) {
        return fail(error, "error", 2);
    } catch (const slides::NonFiniteState& error) {
        return fail(error, "error", 1);
    } catch (const std::exception& error) {
        return fail(error, "internal error", 1);
    }
}
