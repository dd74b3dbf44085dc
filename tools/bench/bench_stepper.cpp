// Particle-steps per second of the stepper: drag (Haider–Levenspiel) + gravity on the
// analytic sech² jet of the default case, for each integrator (adaptiveRungeKutta at its default
// tolerance) and 1e3–1e5 particles.
//
//     build/tools/bench/bench_stepper --benchmark_counters_tabular=true
// items_per_second is particle-steps per second.
#include "../../tests/support/test_scenes.h"
#include "bench_scene.h"
#include "slides/run/stepper.h"

#include <benchmark/benchmark.h>

namespace {

void stepperThroughput(benchmark::State& state) {
    slides::Scene scene = slides::bench::particlesInFlight(state.range(0));
    const auto integrator = slides::integratorNames()[static_cast<std::size_t>(state.range(1))];
    scene.time.integrator = integrator.value;
    const auto carrier = slides::test::carrierOf(scene);
    slides::Stepper stepper(scene, *carrier);
    stepper.step(); // injects everyone
    for (auto _ : state) stepper.step();
    state.SetItemsProcessed(state.iterations() * scene.particles.count);
    state.SetLabel(std::string(integrator.name));
}

BENCHMARK(stepperThroughput)
    ->ArgsProduct({{1000, 10000, 100000}, {0, 1, 2, 3}})
    ->ArgNames({"particles", "integrator"})
    ->UseRealTime() // the stepper runs on every OpenMP thread: wall time, not main-thread CPU
    ->Unit(benchmark::kMicrosecond);

} // namespace
