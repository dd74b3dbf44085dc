#include "slides/run/run_case.h"

#include "slides/io/progress.h"
#include "slides/io/run_output.h"
#include "slides/io/vtk_carrier_grid.h"
#include "slides/io/vtk_damage.h"
#include "slides/io/vtk_deposit.h"
#include "slides/run/rank_agreement.h"
#include "slides/run/rank_gather.h"
#include "slides/run/resolved_scene.h"
#include "slides/run/run_checkpoint.h"
#include "slides/run/run_report.h"
#include "slides/run/stepper.h"

#include <omp.h>

#include <array>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <optional>

namespace slides {

namespace {

/// What a parallel run does not do yet: refused before anything is written (exit status 2).
void requireParallelSupport(const Scene& scene) {
    const auto refuse = [](const std::string& file, const std::string& key,
                           const std::string& what) {
        throw AgreedInputError(
            InputError(file, 0, key, what + " is not supported in parallel runs yet"));
    };
    const std::string dictionary = scene.dictionaryFile.string();
    if (scene.collisions.model != CollisionModel::none)
        refuse(dictionary, "collisions.model", "colliding particles (ghosts across ranks)");
    if (scene.physics.electromagnetic.coulomb.on())
        refuse(dictionary, "physics.electromagnetic.coulomb.model",
               "Coulomb forces between particles (ghosts across ranks)");
    // Ranks sample the carrier together, call for call; adaptive sub-steps differ per rank.
    if (scene.time.integrator == Integrator::adaptiveRungeKutta)
        refuse(dictionary, "time.integrator", "adaptiveRungeKutta (sub-steps differ per rank)");
    // Re-injected ids are counted per injector: the escapes of every rank would need summing.
    if (scene.injection.reinjectEscaped)
        refuse(dictionary, "injection.reinjectEscaped", "re-injecting escaped particles");
    for (const InjectorSettings& injector : scene.injectors)
        if (injector.injection.reinjectEscaped)
            refuse(dictionary, "injectors." + injector.name + ".reinjectEscaped",
                   "re-injecting escaped particles");
    for (const Surface& surface : scene.surfaces) {
        if (surface.interaction == SurfaceInteraction::deposit)
            refuse(dictionary, "surfaces." + surface.name + ".interaction",
                   "a deposit (ghosts across ranks)");
        if (surface.interaction == SurfaceInteraction::erode)
            refuse(dictionary, "surfaces." + surface.name + ".interaction",
                   "an eroding surface (its damage grid summed over ranks)");
    }
}

/// A checkpoint does not hold an eroding surface's damage grid yet: a restart would go on with
/// an empty one, so checkpointing such a run is refused (exit status 2).
void requireCheckpointSupport(const RunOptions& options, const Scene& scene) {
    if (options.checkpointEvery == 0 && !options.restart) return;
    for (const Surface& surface : scene.surfaces)
        if (surface.interaction == SurfaceInteraction::erode)
            throw InputError("command line", 0,
                             options.restart ? "--restart" : "--checkpoint-every",
                             "checkpoints do not hold the damage grid of surface " + surface.name +
                                 " (interaction erode) yet: run it whole");
}

/// The scene resolved on every rank; an input error is one every rank finds alike.
ResolvedScene resolveOnEveryRank(const RunOptions& options, const RankCommunicator& ranks) {
    if (!ranks.parallel()) {
        ResolvedScene resolved = resolveScene(options.caseDirectory, options.overrides);
        requireCheckpointSupport(options, resolved.scene);
        return resolved;
    }
    try {
        ResolvedScene resolved = resolveScene(options.caseDirectory, options.overrides, ranks);
        requireParallelSupport(resolved.scene);
        return resolved;
    } catch (const AgreedError&) {
        throw;
    } catch (const InputError& error) {
        throw AgreedInputError(error);
    }
}

/// Per rank: moving particles, particle-steps, stepping and exchange seconds, particles and
/// bytes sent, MPI calls and seconds in them while stepping, under summary.json's
/// performance.ranks.
nlohmann::json rankFigures(const RankCommunicator& ranks, const Stepper& stepper,
                           const RankExchange& exchange, double steppingSeconds,
                           const MpiTally& steppingMpi) {
    const RankExchangeFigures& own = exchange.figures();
    const std::array<double, 8> mine{static_cast<double>(stepper.cloud().size()),
                                     static_cast<double>(stepper.particleSteps()),
                                     steppingSeconds,
                                     own.seconds,
                                     static_cast<double>(own.particlesSent),
                                     static_cast<double>(own.bytesSent),
                                     static_cast<double>(steppingMpi.calls),
                                     steppingMpi.seconds};
    const auto bytes = std::as_bytes(std::span(mine));
    nlohmann::json figures = nlohmann::json::array();
    for (const Bytes& part : ranks.gather(bytes)) {
        std::array<double, 8> theirs{};
        std::memcpy(theirs.data(), part.data(), sizeof theirs);
        figures.push_back({{"moving", theirs[0]},
                           {"particleSteps", theirs[1]},
                           {"steppingSeconds", theirs[2]},
                           {"exchangeSeconds", theirs[3]},
                           {"particlesSent", theirs[4]},
                           {"bytesSent", theirs[5]},
                           {"mpiCalls", theirs[6]},
                           {"mpiSeconds", theirs[7]}});
    }
    return figures;
}

} // namespace

void runCase(const RunOptions& options, const RankCommunicator& ranks) {
    const int threads = options.threads > 0 ? options.threads : omp_get_max_threads();
    omp_set_num_threads(threads);
    const ResolvedScene resolved = resolveOnEveryRank(options, ranks);
    const Scene& scene = resolved.scene;
    const CarrierField& carrier = *resolved.carrier;
    // A parallel run: rank 0 writes what every rank gathers to it.
    const bool writes = ranks.rank() == 0;
    const bool quiet = options.quiet || !writes;
    if (!quiet) describeRun(resolved, threads);
    if (options.check) { // everything read and the analysis run; nothing is written
        if (!quiet) std::printf("check: the case reads and resolves; nothing written\n");
        return;
    }

    const auto outputDirectory =
        options.output.empty() ? options.caseDirectory / "slides" : options.output;
    const RunFingerprint fingerprint = fingerprintOf(scene.dictionaryFile, scene.time.dt);
    std::optional<CheckpointState> resumed;
    if (options.restart) // every rank reads the whole state; a bad file ends them alike
        agreeOnFailure(ranks, [&] { resumed = readCheckpoint(outputDirectory, fingerprint); });
    std::optional<RunOutput> output;
    agreeOnFailure(ranks, [&] {
        if (writes)
            output.emplace(outputDirectory, runOutputSettings(scene),
                           resumed ? &resumed->frames : nullptr);
        if (scene.carrier.type == CarrierType::none) return; // no gas, nothing to show
        if (writes)
            output->writeCarrier(carrier, scene.domain);
        else
            sampleCarrierLattice(carrier, scene.domain, scene.output.carrierResolution, 0.0);
    });
    std::optional<RankExchange> exchange;
    if (ranks.parallel()) exchange.emplace(dynamic_cast<const RankCarrier&>(carrier));
    Stepper stepper(scene, carrier, exchange ? &*exchange : nullptr);
    ProgressDisplay progress(stderr, quiet);
    // Every rank's part of the state, on the rank that writes.
    const std::size_t exits = carrier.boundaryNames().size() + 1;
    // The damage grids of eroding surfaces (Section 5.2), on a single rank.
    std::optional<DamageOutput> damage;
    if (writes && !ranks.parallel()) damage.emplace(outputDirectory, scene.surfaces);
    const auto writeFrame = [&] {
        if (damage && damage->any())
            damage->writeFrame(stepper.time(), stepper.surfaceImpacts().erosion());
        if (!ranks.parallel()) return output->writeFrame(stepper.snapshot());
        const GatheredRun run = gatherRun(stepper.snapshot(), ranks, exits, scene.surfaces.size());
        if (writes) output->writeFrame(run.snapshot());
    };
    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    Clock::duration stepping{};
    MpiTally steppingMpi; // this segment's, not a restarted run's earlier ones
    // The whole run's times: those of the segments before a restart, and this one's.
    const RunTimes earlier = resumed ? resumed->times : RunTimes{};
    const auto runTimes = [&] {
        using Seconds = std::chrono::duration<double>;
        return RunTimes{earlier.wallSeconds + Seconds(Clock::now() - start).count(),
                        earlier.steppingSeconds + Seconds(stepping).count()};
    };
    double nextFrame = scene.output.interval;
    if (resumed) {
        nextFrame = resumed->nextFrameTime;
        resumeFromCheckpoint(stepper, std::move(*resumed), ranks);
        if (!quiet)
            std::printf("restarted from %s at t = %.6g s (step %ld)\n",
                        (outputDirectory / checkpointFileName).c_str(), stepper.time(),
                        stepper.steps());
    } else {
        writeFrame();
    }
    while (!stepper.finished()) {
        const auto stepStart = Clock::now();
        const MpiTally mpiBefore = RankCommunicator::tally();
        stepper.step();
        stepping += Clock::now() - stepStart;
        const MpiTally mpiAfter = RankCommunicator::tally();
        steppingMpi.calls += mpiAfter.calls - mpiBefore.calls;
        steppingMpi.seconds += mpiAfter.seconds - mpiBefore.seconds;
        if (stepper.time() >= nextFrame * (1 - 1e-12) || stepper.finished()) {
            writeFrame();
            while (nextFrame <= stepper.time() * (1 + 1e-12)) nextFrame += scene.output.interval;
        }
        if (options.checkpointEvery > 0 && stepper.steps() % options.checkpointEvery == 0)
            writeCheckpoint(output ? &*output : nullptr, stepper, nextFrame, runTimes(),
                            fingerprint, ranks, exits, scene.surfaces.size());
        const long done = stepper.injected() - static_cast<long>(stepper.cloud().size());
        double fraction = stepper.time() / scene.time.endTime;
        if (scene.time.stopWhenAllDone)
            fraction = std::max(fraction, static_cast<double>(done) / scene.particles.count);
        progress.update(fraction, stepper.time(), stepper.cloud().size());
    }
    progress.finish();
    const RunTimes times = runTimes();
    const RunMetrics metrics{times.wallSeconds,  times.steppingSeconds,   threads,
                             carrier.describe(), carrier.boundaryNames(), carrier.figures()};
    if (!ranks.parallel()) {
        const RunSnapshot snapshot = stepper.snapshot();
        auto summary = runSummary(resolved, snapshot, metrics);
        if (damage && damage->any())
            summary["erosion"] = damage->finish(stepper.surfaceImpacts().erosion());
        writeDeposit(output->directory(), scene.surfaces, snapshot.arrivals);
        output->finish(snapshot, summary);
        if (!options.quiet) reportRunEnd(snapshot, summary, *output, metrics);
        return;
    }
    const GatheredRun run = gatherRun(stepper.snapshot(), ranks, exits, scene.surfaces.size());
    const nlohmann::json perRank =
        rankFigures(ranks, stepper, *exchange, metrics.steppingSeconds, steppingMpi);
    if (!writes) return;
    auto summary = runSummary(resolved, run.snapshot(), metrics);
    summary["performance"]["ranks"] = perRank;
    writeDeposit(output->directory(), scene.surfaces, run.arrivals);
    output->finish(run.snapshot(), summary);
    if (!options.quiet) reportRunEnd(run.snapshot(), summary, *output, metrics);
}

} // namespace slides
