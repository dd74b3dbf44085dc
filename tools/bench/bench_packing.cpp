// Cost of packed ensembles (integrate/ensemble.h): random sequential addition of equal spheres
// to saturation (φ ≈ 0.384) and to φ = 0.3 (uniform attempts only), and Lubachevsky–Stillinger
// growth to φ = 0.6, in a periodic cube, for 1e4 and 1e5 spheres.
//
//     build/tools/bench/bench_packing --benchmark_counters_tabular=true
// items_per_second is spheres placed per second; attempts (random addition) and sweeps (growth)
// count the work.
#include "slides/integrate/ensemble.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <numbers>
#include <vector>

namespace {

/// Packs `count` spheres of diameter 1 asked for volume fraction φ (beyond saturation for
/// random addition: it stops there).
void pack(benchmark::State& state, slides::PackingMethod method, double fraction) {
    const auto count = static_cast<std::size_t>(state.range(0));
    slides::EnsembleSettings settings;
    settings.method = method;
    settings.region.upper = slides::Vec3::Constant(
        std::cbrt(static_cast<double>(count) * std::numbers::pi / 6 / fraction));
    settings.region.periodic = true;
    const std::vector<double> radii(count, 0.5);
    slides::PackedEnsemble packed;
    for (auto _ : state) packed = slides::packEnsemble(settings, radii, 1, 0);
    state.SetItemsProcessed(state.iterations() * static_cast<long>(packed.centres.size()));
    state.counters["volumeFraction"] = packed.volumeFraction(settings.region.volume());
    state.counters["attempts"] = static_cast<double>(packed.attempts);
    state.counters["sweeps"] = static_cast<double>(packed.sweeps);
}

void randomAdditionToSaturation(benchmark::State& state) {
    pack(state, slides::PackingMethod::randomSequentialAddition, 0.384);
}
void randomAdditionToThreeTenths(benchmark::State& state) {
    pack(state, slides::PackingMethod::randomSequentialAddition, 0.3);
}
void growthToSixTenths(benchmark::State& state) {
    pack(state, slides::PackingMethod::lubachevskyStillinger, 0.6);
}

} // namespace

BENCHMARK(randomAdditionToSaturation)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK(randomAdditionToThreeTenths)
    ->Arg(10000)
    ->Arg(100000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1);
BENCHMARK(growthToSixTenths)->Arg(10000)->Arg(100000)->Unit(benchmark::kSecond)->Iterations(1);
