// Cost of particle collisions: the collide step (broad phase, narrow phase, resolution) on a
// spray, the broad phase alone (its share), and a whole stepper step without collisions, for
// 2e4 and 2e5 particles: a step with collisions costs stepWithoutCollisions + collide.
//
// The spray: the default case's particles (R = 80 µm, Table 5.2) spread uniformly through a
// jet-shaped cylinder 60 mm long at a solids volume fraction of 0.5 % (a dense spray near
// the nozzle), moving at the gas velocity plus ±0.5 m/s cross-span, as in analyticSpray.
//
//     build/tools/bench/bench_collisions --benchmark_counters_tabular=true
// items_per_second is particle-steps per second; times of one run compare: collide against
// stepWithoutCollisions for the cost of collisions, broadPhase against collide for its share.
#include "../../tests/support/test_scenes.h"
#include "bench_scene.h"
#include "slides/collide/cell_grid.h"
#include "slides/collide/particle_collisions.h"
#include "slides/run/stepper.h"

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

namespace {

constexpr double volumeFraction = 0.005, sprayLength = 0.06;

/// Start positions and velocities of the spray, and its positions one step of dt later.
struct Spray {
    slides::ParticleCloud cloud;
    std::vector<slides::Vec3> start;
    std::vector<double> steps;
};

Spray sprayOf(long count, const slides::Scene& scene) {
    const double radius = scene.particles.radius.value;
    const double particleVolume = 4.0 / 3.0 * M_PI * std::pow(radius, 3);
    const double cylinderRadius =
        std::sqrt(count * particleVolume / (volumeFraction * M_PI * sprayLength));
    std::mt19937_64 generator(1);
    std::uniform_real_distribution<double> unit(0, 1);
    Spray spray;
    for (long id = 0; id < count; ++id) {
        const double r = cylinderRadius * std::sqrt(unit(generator));
        const double angle = 2 * M_PI * unit(generator);
        const slides::Vec3 x(sprayLength * unit(generator), r * std::cos(angle),
                             r * std::sin(angle));
        const slides::Vec3 v(20, 0.5 * (2 * unit(generator) - 1), 0.5 * (2 * unit(generator) - 1));
        spray.start.push_back(x);
        spray.cloud.add(static_cast<slides::ParticleId>(id), x + scene.time.dt * v, v, radius);
        spray.cloud.angularVelocity.push_back(slides::Vec3::Zero());
    }
    spray.steps.assign(static_cast<std::size_t>(count), scene.time.dt);
    return spray;
}

slides::Scene sprayScene(long count) {
    slides::Scene scene = slides::bench::particlesInFlight(count);
    scene.collisions.model = slides::CollisionModel::impulse;
    return scene;
}

/// The collide step alone (broad + narrow phase + resolution) on a fresh copy of the spray.
void collide(benchmark::State& state) {
    const slides::Scene scene = sprayScene(state.range(0));
    const Spray spray = sprayOf(state.range(0), scene);
    slides::ParticleCollisions collisions(scene.collisions, scene.particles);
    for (auto _ : state) {
        state.PauseTiming();
        slides::ParticleCloud cloud = spray.cloud;
        state.ResumeTiming();
        collisions.collide(cloud, spray.start, spray.steps);
        benchmark::DoNotOptimize(cloud.velocity.data());
    }
    state.counters["contactsPerStep"] =
        static_cast<double>(collisions.collisions()) / static_cast<double>(state.iterations());
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

/// The broad phase alone: binning and visiting every candidate pair.
void broadPhase(benchmark::State& state) {
    const slides::Scene scene = sprayScene(state.range(0));
    const Spray spray = sprayOf(state.range(0), scene);
    const double cell = 2 * scene.particles.radius.value + 20.1 * scene.time.dt; // as collide
    slides::CellGrid grid;
    for (auto _ : state) {
        grid.build(spray.start, cell);
        long candidates = 0;
        grid.forEachPairInCells(0, grid.occupiedCellCount(),
                                [&](std::uint32_t, std::uint32_t) { ++candidates; });
        benchmark::DoNotOptimize(candidates);
    }
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

/// A whole stepper step without collisions (drag, gravity, exponential midpoint in the analytic
/// jet) with the same number of particles in flight: a step with collisions costs this plus
/// `collide`.
void stepWithoutCollisions(benchmark::State& state) {
    const slides::Scene scene = slides::bench::particlesInFlight(state.range(0));
    const auto carrier = slides::test::carrierOf(scene);
    slides::Stepper stepper(scene, *carrier);
    stepper.step(); // injects everyone
    for (auto _ : state) stepper.step();
    state.SetItemsProcessed(state.iterations() * state.range(0));
}

BENCHMARK(collide)
    ->Arg(20000)
    ->Arg(200000)
    ->ArgName("particles")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(broadPhase)
    ->Arg(20000)
    ->Arg(200000)
    ->ArgName("particles")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
BENCHMARK(stepWithoutCollisions)
    ->Arg(20000)
    ->Arg(200000)
    ->ArgName("particles")
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);

} // namespace
