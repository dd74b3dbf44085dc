// Cost of turbulent dispersion and heat transfer per particle-step, against drag only: the
// default analytic spray (Haider–Levenspiel drag, gravity, exponentialMidpoint) with 1e4
// particles in flight, and uniform jet turbulence (I = 0.1, ℓ = 1 mm: k = 9.4 m²/s²,
// ε = 4.7e3 m²/s³, T_L = 3.8e-4 s ≈ 38 dt, so an eddy lasts many steps while the Langevin
// update draws every step).
//
//     build/tools/bench/bench_dispersion --benchmark_counters_tabular=true
// items_per_second is particle-steps per second; compare the rows of one run (ratio to
// "dragOnly"), not figures across runs.
#include "../../tests/support/test_scenes.h"
#include "slides/config/scene_reader.h"
#include "slides/run/stepper.h"

#include <benchmark/benchmark.h>

namespace {

enum Variant { dragOnly, eddyInteraction, langevin, eddyInteractionAndHeating };

void dispersionCost(benchmark::State& state) {
    slides::Scene scene =
        slides::readScene(std::filesystem::path(SLIDES_SOURCE_DIR) / "foamCases/analyticSpray");
    scene.particles.count = state.range(0);
    scene.injection.mode = slides::InjectionMode::allAtStart;
    scene.time.endTime = 1e9;
    scene.time.stopWhenAllDone = false;
    scene.surfaces.clear(); // keep every particle in flight while timing
    scene.domain = {slides::Vec3::Constant(-1e9), slides::Vec3::Constant(1e9)};
    scene.carrier.turbulence =
        slides::JetTurbulence{slides::TurbulenceScaling::uniform, 0.1, 1e-3, 0.0};
    const auto variant = static_cast<Variant>(state.range(1));
    const char* labels[] = {"dragOnly", "eddyInteraction", "langevin", "eddyInteraction+heating"};
    if (variant == eddyInteraction || variant == eddyInteractionAndHeating)
        scene.physics.dispersion = slides::DispersionModel::eddyInteraction;
    if (variant == langevin) scene.physics.dispersion = slides::DispersionModel::langevin;
    if (variant == eddyInteractionAndHeating) {
        scene.physics.heatTransfer = slides::HeatTransferModel::ranzMarshall;
        scene.particles.specificHeat = 460;
        scene.particles.injectionTemperature = 600;
    }
    const auto carrier = slides::test::carrierOf(scene);
    slides::Stepper stepper(scene, *carrier);
    stepper.step(); // injects everyone
    for (auto _ : state) stepper.step();
    state.SetItemsProcessed(state.iterations() * scene.particles.count);
    state.SetLabel(labels[variant]);
}

BENCHMARK(dispersionCost)
    ->ArgsProduct({{10000}, {dragOnly, eddyInteraction, langevin, eddyInteractionAndHeating}})
    ->ArgNames({"particles", "variant"})
    ->UseRealTime() // the stepper runs on every OpenMP thread: wall time, not main-thread CPU
    ->Unit(benchmark::kMicrosecond);

} // namespace
