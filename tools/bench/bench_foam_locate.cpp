// Locate + interpolate cost per particle-step on a polyhedral-cell mesh (the curved hex block
// of tests/support/foam_test_mesh.h, 20³ and 40³ cells): particles move 0.3 cell per step;
// the walk starts from each particle's previous cell (what the stepper does), against a
// search from scratch (bin grid) every step, with cell, cellPoint or lattice interpolation of U
// (lattice: cellPoint resampled at the mesh spacing, trilinear; points it does not serve take
// the walk and cellPoint, as FoamCarrier does).
//
//     build/tools/bench/bench_foam_locate --benchmark_counters_tabular=true
// items_per_second is particle-steps per second (one thread).
#include "../../tests/support/foam_test_mesh.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/carrier/foam_lattice.h"
#include "slides/carrier/foam_locator.h"
#include "slides/core/name_table.h"

#include <benchmark/benchmark.h>

#include <optional>
#include <random>

namespace {

using namespace slides;

void locateAndInterpolate(benchmark::State& state) {
    const int cellsPerSide = static_cast<int>(state.range(0));
    const bool walk = state.range(1) != 0;
    const auto scheme = static_cast<FoamInterpolation>(state.range(2));
    const FoamMesh mesh = testing::hexBlockMesh(cellsPerSide, testing::wavyDistortion);
    const FoamLocator locator(mesh);
    FoamVolField<Vec3> field;
    for (const Vec3& centre : mesh.cellCentres)
        field.cells.push_back(Vec3(std::sin(centre.x()), centre.y() * centre.z(), 1.0));
    field.patchValues.resize(1);
    const InterpolableField<Vec3> velocity(field, mesh, PointWeights(mesh));
    LatticeFrame frame;
    frame.origin = mesh.boundsMin;
    frame.spacing = 1.0 / cellsPerSide;
    for (int d = 0; d < 3; ++d)
        frame.nodes[d] =
            2 + static_cast<int>((mesh.boundsMax[d] - mesh.boundsMin[d]) * cellsPerSide);
    std::optional<FoamLattice> lattice;
    if (scheme == FoamInterpolation::lattice)
        lattice.emplace(frame, [&](const Vec3& x) -> std::optional<GasValues> {
            const TetLocation at = locator.locate(x, -1);
            if (!at.found()) return std::nullopt;
            return GasValues{velocity.value(mesh, at), {}};
        });

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
            if (LatticeWeights weights; lattice && lattice->locate(point, weights)) {
                sum += lattice->velocity(weights);
                continue;
            }
            const TetLocation at = locator.locate(point, walk ? cells[i] : -1);
            cells[i] = at.cell;
            if (at.found())
                sum += scheme == FoamInterpolation::cell ? velocity.cells[at.cell]
                                                         : velocity.value(mesh, at);
        }
    }
    benchmark::DoNotOptimize(sum);
    state.SetItemsProcessed(state.iterations() * particles);
    state.SetLabel(std::string(walk ? "walk " : "search ") +
                   std::string(nameOf(foamInterpolationNames(), scheme)));
}

BENCHMARK(locateAndInterpolate)
    ->ArgsProduct({{20, 40}, {1, 0}, {0, 1, 2}}) // scheme: cell, cellPoint, lattice
    ->ArgNames({"n", "walk", "scheme"})
    ->Unit(benchmark::kMicrosecond);

} // namespace
