// Locate + interpolate cost per particle-step on a polyhedral-cell mesh (the curved hex block
// of tests/support/foam_test_mesh.h, 20³ and 40³ cells): particles move 0.3 cell per step;
// the walk starts from each particle's previous cell (what the stepper does), against a
// search from scratch (bin grid) every step, with cellPoint or cell interpolation of U.
//
//     build/tools/bench/bench_foam_locate --benchmark_counters_tabular=true
// items_per_second is particle-steps per second (one thread).
#include "../../tests/support/foam_test_mesh.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/carrier/foam_locator.h"

#include <benchmark/benchmark.h>

#include <random>

namespace {

using namespace slides;

void locateAndInterpolate(benchmark::State& state) {
    const int cellsPerSide = static_cast<int>(state.range(0));
    const bool walk = state.range(1) != 0;
    const bool cellPoint = state.range(2) != 0;
    const FoamMesh mesh = testing::hexBlockMesh(cellsPerSide, testing::wavyDistortion);
    const FoamLocator locator(mesh);
    FoamVolField<Vec3> field;
    for (const Vec3& centre : mesh.cellCentres)
        field.cells.push_back(Vec3(std::sin(centre.x()), centre.y() * centre.z(), 1.0));
    field.patchValues.resize(1);
    const InterpolableField<Vec3> velocity(field, mesh, PointWeights(mesh));

    const int particles = 10000;
    std::mt19937 random(1);
    std::uniform_real_distribution<double> unit(0.05, 0.95);
    std::vector<Vec3> reference(particles), direction(particles);
    std::vector<int> cells(particles, -1);
    for (int i = 0; i < particles; ++i) {
        reference[i] = Vec3(unit(random), unit(random), unit(random));
        direction[i] =
            Vec3(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5).normalized();
    }
    const double stepLength = 0.3 / cellsPerSide;
    long step = 0;
    Vec3 sum = Vec3::Zero();
    for (auto _ : state) {
        ++step;
        for (int i = 0; i < particles; ++i) {
            // Back and forth along a line through the box, inside it.
            const double s =
                stepLength *
                static_cast<double>((step + i) % 40 < 20 ? (step + i) % 20 : 20 - (step + i) % 20);
            const Vec3 point = testing::wavyDistortion(reference[i] + s * direction[i] * 0.5);
            const TetLocation at = locator.locate(point, walk ? cells[i] : -1);
            cells[i] = at.cell;
            if (at.found()) sum += cellPoint ? velocity.value(mesh, at) : velocity.cells[at.cell];
        }
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations() * particles);
    state.SetLabel(std::string(walk ? "walk" : "search") + (cellPoint ? " cellPoint" : " cell"));
}

BENCHMARK(locateAndInterpolate)
    ->ArgsProduct({{20, 40}, {1, 0}, {1, 0}})
    ->ArgNames({"n", "walk", "cellPoint"})
    ->Unit(benchmark::kMicrosecond);

} // namespace
