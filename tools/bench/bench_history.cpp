// Cost per particle-step and memory per particle of the unsteady terms, on the analytic jet of
// the default case: drag only (exponentialMidpoint), drag + Basset history (window + exponential
// tail, accuracy 1e-3), and the full Maxey–Riley equation (history, added mass, pressure
// gradient, Saffman–Mei + Magnus lift, spin), and the same with the spin's history (Eq. 3.19);
// drag + Mei & Adrian's and Kim's finite-Reynolds history (physics/finite_reynolds_history.h).
//
//     build/tools/bench/bench_history --benchmark_counters_tabular=true
// items_per_second is particle-steps per second; bytes_per_particle counts the kinematic arrays
// (id, x, v, R) plus the model state. Compare the rows of one run as ratios.
#include "../../tests/support/test_scenes.h"
#include "bench_scene.h"
#include "slides/run/stepper.h"

#include <benchmark/benchmark.h>

#include <string>

namespace {

enum Variant { dragOnly, dragHistory, fullMaxeyRiley, fullWithSpinHistory, dragMeiAdrian, dragKim };

void unsteadyCost(benchmark::State& state) {
    slides::Scene scene = slides::bench::particlesInFlight(state.range(0));
    // A long horizon for the tail (10⁴ steps), as in a long run; the timed steps stay inside it.
    scene.time.endTime = 1e4 * scene.time.dt;
    const auto variant = static_cast<Variant>(state.range(1));
    auto& physics = scene.physics;
    if (variant != dragOnly) physics.history = slides::HistoryModel::basset;
    if (variant == dragMeiAdrian) physics.history = slides::HistoryModel::meiAdrian;
    if (variant == dragKim) physics.history = slides::HistoryModel::kim;
    if (variant == fullMaxeyRiley || variant == fullWithSpinHistory) {
        physics.addedMass = physics.pressureGradient = physics.spin = true;
        physics.lift = slides::LiftModel::saffmanMeiMagnus;
    }
    physics.spinHistory = variant == fullWithSpinHistory;
    const auto carrier = slides::test::carrierOf(scene);
    slides::Stepper stepper(scene, *carrier);
    // Injects everyone, then 100 steps: past the first 64 intervals of a release with slip,
    // where the finite-Reynolds memories weight ℓ_c per part (one κ more per tail term).
    for (int k = 0; k < 101; ++k) stepper.step();
    for (auto _ : state) {
        if (stepper.finished()) state.SkipWithError("ran past the tail's horizon");
        stepper.step();
    }
    const auto& cloud = stepper.cloud();
    state.SetItemsProcessed(state.iterations() * scene.particles.count);
    state.counters["bytes_per_particle"] =
        static_cast<double>(sizeof(slides::ParticleId) + 2 * sizeof(slides::Vec3) + sizeof(double) +
                            cloud.stateWidth * sizeof(double));
    state.SetLabel(variant == dragOnly         ? "drag only"
                   : variant == dragHistory    ? "drag + history"
                   : variant == fullMaxeyRiley ? "full Maxey-Riley"
                   : variant == dragMeiAdrian  ? "drag + Mei-Adrian history"
                   : variant == dragKim        ? "drag + Kim history"
                                               : "full + spin history");
}

BENCHMARK(unsteadyCost)
    ->ArgsProduct({{1000, 10000},
                   {dragOnly, dragHistory, fullMaxeyRiley, fullWithSpinHistory, dragMeiAdrian,
                    dragKim}})
    ->ArgNames({"particles", "variant"})
    ->UseRealTime()
    ->Unit(benchmark::kMicrosecond);

} // namespace
