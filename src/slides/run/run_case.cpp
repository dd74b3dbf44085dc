#include "slides/run/run_case.h"

#include "slides/io/progress.h"
#include "slides/io/run_output.h"
#include "slides/io/vtk_deposit.h"
#include "slides/run/resolved_scene.h"
#include "slides/run/run_checkpoint.h"
#include "slides/run/run_report.h"
#include "slides/run/stepper.h"

#include <omp.h>

#include <chrono>
#include <cstdio>
#include <optional>

namespace slides {

void runCase(const RunOptions& options) {
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
    omp_set_num_threads(threads);
    const ResolvedScene resolved = resolveScene(options.caseDirectory, options.overrides);
    const Scene& scene = resolved.scene;
    const CarrierField& carrier = *resolved.carrier;
    if (!options.quiet) describeRun(resolved, threads);
    if (options.check) { // everything read and the analysis run; nothing is written
        if (!options.quiet) std::printf("check: the case reads and resolves; nothing written\n");
        return;
    }

    const auto outputDirectory =
        options.output.empty() ? options.caseDirectory / "slides" : options.output;
    const RunFingerprint fingerprint = fingerprintOf(scene.dictionaryFile, scene.time.dt);
    std::optional<CheckpointState> resumed;
    if (options.restart) resumed = readCheckpoint(outputDirectory, scene.output.hdf5, fingerprint);
    RunOutput output(outputDirectory, runOutputSettings(scene),
                     resumed ? &resumed->frames : nullptr);
    if (scene.carrier.type != CarrierType::none) // no gas, nothing to show
        output.writeCarrier(carrier, scene.domain);
    Stepper stepper(scene, carrier);
    ProgressDisplay progress(stderr, options.quiet);

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    Clock::duration stepping{};
    double nextFrame = scene.output.interval;
    if (resumed) {
        nextFrame = resumed->nextFrameTime;
        resumeFromCheckpoint(stepper, std::move(*resumed));
        if (!options.quiet)
            std::printf("restarted from %s at t = %.6g s (step %ld)\n",
                        (outputDirectory / checkpointFileName).c_str(), stepper.time(),
                        stepper.steps());
    } else {
        output.writeFrame(stepper.snapshot());
    }
    while (!stepper.finished()) {
        const auto stepStart = Clock::now();
        stepper.step();
        stepping += Clock::now() - stepStart;
        if (stepper.time() >= nextFrame * (1 - 1e-12) || stepper.finished()) {
            output.writeFrame(stepper.snapshot());
            while (nextFrame <= stepper.time() * (1 + 1e-12)) nextFrame += scene.output.interval;
        }
        if (options.checkpointEvery > 0 && stepper.steps() % options.checkpointEvery == 0)
            writeCheckpoint(output, stepper, nextFrame, fingerprint);
        const long done = stepper.injected() - static_cast<long>(stepper.cloud().size());
        double fraction = stepper.time() / scene.time.endTime;
        if (scene.time.stopWhenAllDone)
            fraction = std::max(fraction, static_cast<double>(done) / scene.particles.count);
        progress.update(fraction, stepper.time(), stepper.cloud().size());
    }
    progress.finish();
    const RunMetrics metrics{std::chrono::duration<double>(Clock::now() - start).count(),
                             std::chrono::duration<double>(stepping).count(),
                             threads,
                             carrier.describe(),
                             carrier.boundaryNames(),
                             carrier.figures()};
    const RunSnapshot snapshot = stepper.snapshot();
    const auto summary = runSummary(resolved, snapshot, metrics);
    writeDeposit(output.directory(), scene.surfaces, snapshot.arrivals);
    output.finish(snapshot, summary);
    if (!options.quiet) reportRunEnd(snapshot, summary, output, metrics);
}

} // namespace slides
