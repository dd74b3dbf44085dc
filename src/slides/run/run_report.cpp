#include "slides/run/run_report.h"

#include "slides/analysis/scene_analysis_json.h"
#include "slides/config/scene_json.h"
#include "slides/core/name_table.h"
#include "slides/integrate/mean_response_time.h"

#include <cstdio>

namespace slides {

void describeRun(const ResolvedScene& resolved, int threads) {
    const Scene& scene = resolved.scene;
    const double meanRadius = scene.particles.radius.meanRadius();
    const double responseTime = meanStokesResponseTime(scene.particles, scene.fluid);
    std::printf("slides-track %s: case %s\n", SLIDES_VERSION, scene.caseDirectory.c_str());
    std::printf("  carrier    %s\n", resolved.carrier->describe().c_str());
    std::printf("  particles  %ld, mean radius %.3g m, density %.4g kg/m^3, Stokes response "
                "time %.3g s\n",
                scene.particles.count, meanRadius, scene.particles.density, responseTime);
    for (std::size_t k = 1; k < scene.particles.species.size(); ++k) {
        const double density = scene.particles.species[k].density;
        std::printf("             species %zu: density %.4g kg/m^3, Stokes response time %.3g s\n",
                    k, density, responseTime * density / scene.particles.density);
    }
    std::string integrator(nameOf(integratorNames(), scene.time.integrator));
    if (scene.time.integrator == Integrator::adaptiveRungeKutta) {
        char tolerance[40];
        std::snprintf(tolerance, sizeof tolerance, " (tolerance %g)", scene.time.tolerance);
        integrator += tolerance;
    }
    std::fputs(describeAnalysis(resolved.analysis).c_str(), stdout);
    std::printf("  time       dt %.3g s (%s, %.3g response times), end %.3g s, %s, %d thread%s\n",
                scene.time.dt, resolved.analysis.timeStepGiven ? "given" : "from the analysis",
                scene.time.dt / responseTime, scene.time.endTime, integrator.c_str(), threads,
                threads == 1 ? "" : "s");
    if (scene.time.integrator == Integrator::explicitEuler && scene.time.dt > 2 * responseTime)
        std::printf("  warning    explicitEuler is unstable for dt > 2 response times; use an "
                    "exponential integrator\n");
    std::fflush(stdout);
}

namespace {

/// Each particle's density by its id when the particles differ; empty when alike.
std::function<double(std::uint64_t)> densityOf(const Scene& scene) {
    if (scene.particles.alike()) return {};
    return [particles = scene.particles](std::uint64_t id) { return particles.densityOf(id); };
}

} // namespace

RunOutputSettings runOutputSettings(const Scene& scene) {
    return {.output = scene.output,
            .caseDirectory = scene.caseDirectory,
            .temperature = scene.physics.heatTransfer != HeatTransferModel::none,
            .spin = tracksSpin(scene),
            .electromagnetic = scene.physics.electromagnetic,
            .injectorIds = injectorIds(scene),
            .densityOf = densityOf(scene)};
}

SummaryInputs summaryInputs(const Scene& scene, const SceneAnalysis* analysis) {
    return {.caseDirectory = scene.caseDirectory,
            .requested = scene.particles.count,
            .surfaces = scene.surfaces,
            .nozzle = scene.nozzle,
            .temperature = scene.physics.heatTransfer != HeatTransferModel::none,
            .collisions = scene.collisions.model != CollisionModel::none,
            .stokesResponseTime = meanStokesResponseTime(scene.particles, scene.fluid),
            .sceneAnalysis = analysis ? sceneAnalysisJson(*analysis) : nlohmann::json(),
            .settings = sceneSettings(scene),
            .injectorNames = injectorNames(scene),
            .injectorIds = injectorIds(scene)};
}

nlohmann::json runSummary(const ResolvedScene& resolved, const RunSnapshot& snapshot,
                          const RunMetrics& metrics) {
    return runSummary(snapshot, summaryInputs(resolved.scene, &resolved.analysis), metrics);
}

void reportRunEnd(const RunSnapshot& snapshot, const nlohmann::json& summary,
                  const RunOutput& output, const RunMetrics& metrics) {
    const RunCounters& counters = snapshot.counters;
    std::printf("done: t = %.4g s in %ld steps, %.3g s wall (%.3g s stepping, %.3g "
                "particle-steps/s)\n",
                counters.time, counters.steps, metrics.wallSeconds, metrics.steppingSeconds,
                summary["performance"]["particleStepsPerSecond"].get<double>());
    std::printf("  injected %ld, arrived %zu, escaped %ld, still moving %zu\n", counters.injected,
                snapshot.arrivals.size(), counters.escaped, snapshot.cloud.size());
    if (counters.escaped > 0) {
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

} // namespace slides
