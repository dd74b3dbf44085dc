#include "slides/io/summary.h"

#include "slides/integrate/injection_settings.h"
#include "slides/surfaces/deposit_metrics.h"

#include <cmath>
#include <numeric>

namespace slides {

namespace {

/// Mean, standard deviation, rms and extremes of one quantity over the arrivals at one
/// surface (two passes, so the deviation does not cancel catastrophically).
nlohmann::json statistics(const std::vector<double>& values) {
    if (values.empty()) return nullptr;
    const double n = static_cast<double>(values.size());
    double sum = 0, low = values.front(), high = values.front();
    for (double value : values) {
        sum += value;
        low = std::min(low, value);
        high = std::max(high, value);
    }
    const double mean = sum / n;
    double deviations = 0;
    for (double value : values) deviations += (value - mean) * (value - mean);
    const double variance = deviations / n;
    return {{"mean", mean},
            {"standardDeviation", std::sqrt(variance)},
            {"rms", std::sqrt(variance + mean * mean)},
            {"min", low},
            {"max", high}};
}

nlohmann::json arrivalsAt(const SummaryInputs& inputs, const RunSnapshot& snapshot, int surface) {
    const Surface& plane = inputs.surfaces[static_cast<std::size_t>(surface)];
    const JetNozzle& nozzle = inputs.nozzle;
    std::vector<double> impactSpeed, normalSpeed, distanceFromAxis, time, temperature;
    for (const auto& arrival : snapshot.arrivals) {
        if (arrival.surface != surface) continue;
        impactSpeed.push_back(arrival.velocity.norm());
        normalSpeed.push_back(-arrival.velocity.dot(plane.normal));
        const Vec3 fromNozzle = arrival.position - nozzle.centre;
        distanceFromAxis.push_back((fromNozzle - fromNozzle.dot(nozzle.axis) * nozzle.axis).norm());
        time.push_back(arrival.time);
        temperature.push_back(arrival.temperature);
    }
    nlohmann::json result = {{"count", impactSpeed.size()},
                             {"impactSpeed", statistics(impactSpeed)},
                             {"impactNormalSpeed", statistics(normalSpeed)},
                             {"distanceFromAxis", statistics(distanceFromAxis)},
                             {"arrivalTime", statistics(time)}};
    if (inputs.temperature) result["temperature"] = statistics(temperature);
    return result;
}

/// Arrivals per injector and surface: {"gunA": {"target": 120}, ...}.
nlohmann::json arrivedByInjector(const SummaryInputs& inputs, const RunSnapshot& snapshot) {
    const auto& names = inputs.injectorNames;
    std::vector<std::vector<std::uint64_t>> counts(
        names.size(), std::vector<std::uint64_t>(inputs.surfaces.size(), 0));
    for (const Arrival& arrival : snapshot.arrivals)
        ++counts[static_cast<std::size_t>(inputs.injectorIds.injectorOf(arrival.id))]
                [static_cast<std::size_t>(arrival.surface)];
    nlohmann::json byInjector = nlohmann::json::object();
    for (std::size_t i = 0; i < names.size(); ++i) {
        byInjector[names[i]] = nlohmann::json::object();
        for (std::size_t s = 0; s < inputs.surfaces.size(); ++s)
            byInjector[names[i]][inputs.surfaces[s].name] = counts[i][s];
    }
    return byInjector;
}

} // namespace

nlohmann::json escapedThrough(const RunCounters& counters,
                              const std::vector<std::string>& patches) {
    nlohmann::json counts = nlohmann::json::object();
    const auto& exits = counters.escapedThrough;
    for (std::size_t exit = 0; exit < exits.size(); ++exit)
        if (exits[exit] > 0)
            counts[exit == 0 || exit > patches.size() ? "domain" : patches[exit - 1]] = exits[exit];
    return counts;
}

nlohmann::json runSummary(const RunSnapshot& snapshot, const SummaryInputs& inputs,
                          const RunMetrics& metrics) {
    const RunCounters& counters = snapshot.counters;
    const std::span<const Surface> surfaces = inputs.surfaces;
    nlohmann::json summary;
    summary["slidesTrack"] = SLIDES_VERSION;
    summary["case"] = inputs.caseDirectory.string();
    summary["carrier"] = metrics.carrier;
    for (const auto& [name, value] : metrics.carrierFigures)
        summary["carrierFigures"][name] = value;

    nlohmann::json arrived = nlohmann::json::object();
    nlohmann::json arrivals = nlohmann::json::object();
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        arrivals[surfaces[s].name] = arrivalsAt(inputs, snapshot, static_cast<int>(s));
        arrived[surfaces[s].name] = arrivals[surfaces[s].name]["count"];
    }
    summary["particles"] = {{"requested", inputs.requested},
                            {"injected", counters.injected},
                            {"arrived", arrived},
                            {"escaped", counters.escaped},
                            {"escapedThrough", escapedThrough(counters, metrics.boundaryNames)},
                            {"active", snapshot.cloud.size()}};
    summary["arrivals"] = arrivals;
    if (!inputs.injectorNames.empty())
        summary["particles"]["arrivedByInjector"] = arrivedByInjector(inputs, snapshot);
    // Constant mass flow: the particles injected in place of escaped ones, beyond "injected".
    if (!counters.reinjected.empty()) {
        summary["particles"]["reinjected"] =
            std::accumulate(counters.reinjected.begin(), counters.reinjected.end(), 0UL);
        for (std::size_t j = 0; j < inputs.injectorNames.size(); ++j)
            summary["particles"]["reinjectedByInjector"][inputs.injectorNames[j]] =
                counters.reinjected[j];
    }
    if (counters.collisions > 0 || inputs.collisions)
        summary["collisions"] = {{"particlePairs", counters.collisions}};
    for (std::size_t s = 0; s < surfaces.size(); ++s) {
        const Surface& plane = surfaces[s];
        if (plane.interaction == SurfaceInteraction::absorb) continue;
        const std::uint64_t rebounds = counters.rebounds[s];
        summary["rebounds"][plane.name] = rebounds;
        if (plane.interaction != SurfaceInteraction::deposit) continue;
        const DepositMetrics deposit =
            depositMetrics(plane, static_cast<int>(s), snapshot.arrivals, counters.injected);
        summary["deposition"][plane.name] = {
            {"stuck", deposit.stuck},
            {"depositedFraction", deposit.fraction},
            {"depositHeight", deposit.height},
            {"depositHeightToNozzleRadius", deposit.height / inputs.nozzle.radius},
            {"meanRadius", deposit.meanRadius},
            {"lowestCentre", deposit.lowestCentre},
            {"highestCentre", deposit.highestCentre},
            {"note", "Eq. 5.12: n_dep = stuck / injected, h_dep = (x_max + R_av) - (x_min - "
                     "R_av), x = centre height above the plane"}};
    }

    summary["responseTime"] = {{"stokes", inputs.stokesResponseTime},
                               {"note", "tau_St = 2 rho_p R^2 / (9 rho_f nu) at the mean radius"}};
    summary["time"] = {{"end", counters.time}, {"steps", counters.steps}};
    const double particleSteps = static_cast<double>(counters.particleSteps);
    // Particle-steps per second of the stepping alone (output time is reported beside it).
    summary["performance"] = {
        {"wallSeconds", metrics.wallSeconds},
        {"steppingSeconds", metrics.steppingSeconds},
        {"threads", metrics.threads},
        {"particleSteps", counters.particleSteps},
        {"particleStepsPerSecond",
         metrics.steppingSeconds > 0 ? particleSteps / metrics.steppingSeconds : 0.0}};
    // A cost, not a result: a restarted run builds its list once more.
    if (snapshot.neighbourListBuilds)
        summary["performance"]["neighbourListBuilds"] = *snapshot.neighbourListBuilds;
    if (snapshot.adaptiveSteps)
        summary["performance"]["adaptiveSteps"] = {{"attempted", snapshot.adaptiveSteps->attempted},
                                                   {"rejected", snapshot.adaptiveSteps->rejected}};
    if (!inputs.sceneAnalysis.is_null()) summary["sceneAnalysis"] = inputs.sceneAnalysis;
    summary["settings"] = inputs.settings;
    return summary;
}

} // namespace slides
