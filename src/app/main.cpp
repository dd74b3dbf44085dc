// slides-track: track particles through a carrier-gas field and write the results for ParaView.
//
//     slides-track foamCases/analyticSpray            # results in foamCases/analyticSpray/slides/
//     slides-track CASE --output DIR --dt 1e-5 --threads 2
//     slides-track foamCases/impingingJet --time 500     # an OpenFOAM case, its time 500
//     slides-track CASE --checkpoint-every 500     # after a crash: slides-track CASE --restart
// Exit status: 0 success, 2 bad input (one message naming file, line and key), 1 internal error.
#include "slides/analysis/scene_analysis.h"
#include "slides/carrier/make_carrier.h"
#include "slides/config/scene_keys.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/core/name_table.h"
#include "slides/core/thread_waits.h"
#include "slides/integrate/mean_response_time.h"
#include "slides/run/stepper.h"
#include "slides/io/atomic_file.h"
#include "slides/io/checkpoint.h"
#include "slides/io/progress.h"
#include "slides/io/run_output.h"
#include "slides/io/summary.h"
#include "slides/surfaces/patch_wall.h"

#include <CLI/CLI.hpp>
#include <omp.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <optional>

namespace {

struct Options {
    std::string caseDirectory;
    std::string output;
    std::optional<double> endTime;
    std::optional<double> dt;
    std::optional<std::string> time;
    int threads = 0;
    long checkpointEvery = 0; ///< steps between checkpoints; 0: none
    bool restart = false;
    bool quiet = false;
    bool listKeys = false;
};

/// Command-line overrides of the dictionary, checked like dictionary values.
void applyOverrides(const Options& options, slides::Scene& scene) {
    if (options.endTime) {
        if (!(*options.endTime > 0))
            throw slides::InputError("command line", 0, "--end-time", "must be positive");
        scene.time.endTime = *options.endTime;
    }
    if (options.dt) {
        if (!(*options.dt > 0))
            throw slides::InputError("command line", 0, "--dt", "must be positive");
        scene.time.dt = *options.dt;
    }
    if (options.time) {
        if (scene.carrier.type != slides::CarrierType::foamField)
            throw slides::InputError("command line", 0, "--time",
                                     "only an OpenFOAM carrier (foamField) has time directories");
        scene.carrier.foamTime = *options.time;
    }
    if (scene.time.dt > scene.time.endTime)
        throw slides::InputError("command line", 0, "--dt", "is longer than the end time");
}

void describeRun(const slides::Scene& scene, const slides::CarrierField& carrier,
                 const slides::SceneAnalysis& analysis, int threads) {
    const double meanRadius = scene.particles.radius.meanRadius();
    const double responseTime = slides::meanStokesResponseTime(scene.particles, scene.fluid);
    std::printf("slides-track %s: case %s\n", SLIDES_VERSION, scene.caseDirectory.c_str());
    std::printf("  carrier    %s\n", carrier.describe().c_str());
    std::printf("  particles  %ld, mean radius %.3g m, density %.4g kg/m^3, Stokes response "
                "time %.3g s\n",
                scene.particles.count, meanRadius, scene.particles.density, responseTime);
    const std::string integrator(slides::nameOf(slides::integratorNames(), scene.time.integrator));
    std::fputs(slides::describeAnalysis(analysis).c_str(), stdout);
    std::printf("  time       dt %.3g s (%s, %.3g response times), end %.3g s, %s, %d thread%s\n",
                scene.time.dt, analysis.timeStepGiven ? "given" : "from the analysis",
                scene.time.dt / responseTime, scene.time.endTime, integrator.c_str(), threads,
                threads == 1 ? "" : "s");
    if (scene.time.integrator == slides::Integrator::explicitEuler &&
        scene.time.dt > 2 * responseTime)
        std::printf("  warning    explicitEuler is unstable for dt > 2 response times; use an "
                    "exponential integrator\n");
    std::fflush(stdout);
}

int run(const Options& options) {
    slides::Scene scene = slides::readScene(options.caseDirectory);
    applyOverrides(options, scene);
    const auto carrier = slides::makeCarrier(scene);
    if (scene.domainFromCarrier) scene.domain = carrier->bounds().value();
    slides::placePatchSurfaces(scene, *carrier);
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
    omp_set_num_threads(threads);
    const slides::SceneAnalysis analysis = slides::analyseScene(scene, *carrier);
    slides::applyAnalysis(analysis, scene);
    if (!options.quiet) describeRun(scene, *carrier, analysis, threads);

    const auto outputDirectory = options.output.empty()
                                     ? std::filesystem::path(options.caseDirectory) / "slides"
                                     : std::filesystem::path(options.output);
    const slides::RunFingerprint fingerprint = slides::fingerprintOf(scene);
    std::optional<slides::RunState> resumed;
    if (options.restart)
        resumed = slides::resumeFromCheckpoint(outputDirectory, scene, fingerprint);
    slides::RunOutput output(outputDirectory, scene, *carrier,
                             resumed ? &resumed->frames : nullptr);
    slides::Stepper stepper(scene, *carrier);
    slides::ProgressDisplay progress(stderr, options.quiet);

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    Clock::duration stepping{};
    double nextFrame = scene.output.interval;
    if (resumed) {
        stepper.resume(resumed->counters, std::move(resumed->cloud), std::move(resumed->arrivals),
                       std::move(resumed->springs));
        nextFrame = resumed->nextFrameTime;
        if (!options.quiet)
            std::printf("restarted from %s at t = %.6g s (step %ld)\n",
                        (outputDirectory / slides::checkpointFileName).c_str(), stepper.time(),
                        stepper.steps());
    } else {
        output.writeFrame(stepper);
    }
    while (!stepper.finished()) {
        const auto stepStart = Clock::now();
        stepper.step();
        stepping += Clock::now() - stepStart;
        if (stepper.time() >= nextFrame * (1 - 1e-12) || stepper.finished()) {
            output.writeFrame(stepper);
            while (nextFrame <= stepper.time() * (1 + 1e-12)) nextFrame += scene.output.interval;
        }
        if (options.checkpointEvery > 0 && stepper.steps() % options.checkpointEvery == 0)
            slides::writeCheckpoint(output, stepper, nextFrame, fingerprint);
        const long done = stepper.injected() - static_cast<long>(stepper.cloud().size());
        double fraction = stepper.time() / scene.time.endTime;
        if (scene.time.stopWhenAllDone)
            fraction = std::max(fraction, static_cast<double>(done) / scene.particles.count);
        progress.update(fraction, stepper.time(), stepper.cloud().size());
    }
    progress.finish();
    const double wallSeconds = std::chrono::duration<double>(Clock::now() - start).count();
    const double steppingSeconds = std::chrono::duration<double>(stepping).count();
    const auto summary =
        slides::runSummary(scene, stepper,
                           {wallSeconds, steppingSeconds, threads, carrier->describe(),
                            carrier->boundaryNames(), carrier->figures(), &analysis});
    output.finish(stepper, summary);

    if (!options.quiet) {
        std::printf("done: t = %.4g s in %ld steps, %.3g s wall (%.3g s stepping, %.3g "
                    "particle-steps/s)\n",
                    stepper.time(), stepper.steps(), wallSeconds, steppingSeconds,
                    summary["performance"]["particleStepsPerSecond"].get<double>());
        std::printf("  injected %ld, arrived %zu, escaped %ld, still moving %zu\n",
                    stepper.injected(), stepper.arrivals().size(), stepper.escaped(),
                    stepper.cloud().size());
        if (stepper.escaped() > 0) {
            std::printf("  escaped through");
            for (const auto& [exit, count] : summary["particles"]["escapedThrough"].items())
                std::printf(" %s %ld", exit.c_str(), count.get<long>());
            std::printf("\n");
        }
        if (summary.contains("deposition"))
            for (const auto& [surface, deposit] : summary["deposition"].items())
                std::printf("  deposit on %s: %ld stuck, n_dep = %.4g, h_dep = %.4g m (Eq. 5.12)\n",
                            surface.c_str(), deposit["stuck"].get<long>(),
                            deposit["depositedFraction"].get<double>(),
                            deposit["depositHeight"].get<double>());
        std::printf("results in %s/ (%zu frames)\n  open in ParaView:  paraview %s\n"
                    "  summary:           %s\n",
                    output.directory().c_str(), output.frames().size(),
                    (output.directory() / "particles.pvd").c_str(),
                    (output.directory() / "summary.json").c_str());
    }
    return 0;
}

} // namespace

int main(int argc, char** argv) {
    slides::sleepWhileWaitingForWork(argv);
    CLI::App app{"slides-track: Lagrangian particle tracking in a carrier-gas jet.\n"
                 "CASE holds constant/slidesProperties; results go to CASE/slides/."};
    Options options;
    app.add_option("CASE", options.caseDirectory, "case directory")->check(CLI::ExistingDirectory);
    app.add_option("--output", options.output, "output directory (default CASE/slides)");
    app.add_option("--end-time", options.endTime, "end time [s], overrides time.endTime");
    app.add_option("--dt", options.dt, "time step [s], overrides time.dt");
    app.add_option(
        "--time", options.time,
        "OpenFOAM time directory (latestTime or a value), overrides foamFieldCoeffs.time");
    app.add_option("--threads", options.threads, "threads (default: all cores)")
        ->check(CLI::Range(1, 4096).description("a whole number from 1 to 4096"));
    app.add_option("--checkpoint-every", options.checkpointEvery,
                   "write OUTPUT/checkpoint.h5 every N steps (whole state, atomically)")
        ->check(CLI::Range(1L, 1000000000L).description("a whole number of steps ≥ 1"));
    app.add_flag("--restart", options.restart,
                 "continue from OUTPUT/checkpoint.h5; results identical to an uninterrupted run");
    app.add_flag("--quiet", options.quiet, "no progress display or report");
    app.add_flag("--list-keys", options.listKeys,
                 "print the table of slidesProperties keys (markdown) and exit");
    app.set_version_flag("--version", std::string("slides-track ") + SLIDES_VERSION);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        const int status = app.exit(error);
        return status == 0 ? 0 : 2;
    }
    if (options.listKeys) {
        std::cout << slides::sceneKeysMarkdown();
        return 0;
    }
    if (options.caseDirectory.empty()) {
        std::cerr << "slides-track: error: no CASE directory given (see --help)\n";
        return 2;
    }
    try {
        return run(options);
    } catch (const slides::InputError& error) {
        std::fprintf(stderr, "\nslides-track: error: %s\n", error.what());
        return 2;
    } catch (const slides::OutputError& error) {
        std::fprintf(stderr, "\nslides-track: error: %s\n", error.what());
        return 2;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "\nslides-track: internal error: %s\n", error.what());
        return 1;
    }
}
