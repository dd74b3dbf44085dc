// ctest-labels: unit
// ProcessorClearance (run/processor_clearance.h): a particle judged to have stayed in its cell's
// ball crossed no processor face. Checked on a block mesh whose x = 0 side is a processor patch:
// no point of a processor face is ever judged stayed from any cell, every point judged stayed
// lies on the part's side of the plane, and cells far from the patch do skip their walk.
#include "../support/foam_test_mesh.h"
#include "slides/carrier/foam_locator.h"
#include "slides/run/processor_clearance.h"

#include <gtest/gtest.h>

#include <random>

namespace slides {
namespace {

constexpr int cellsPerSide = 8;

/// The block mesh with its x = 0 faces (the first side of its walls) a processor patch.
FoamMesh meshWithProcessorSide(const std::function<Vec3(const Vec3&)>& distortion) {
    FoamMesh mesh = testing::hexBlockMesh(cellsPerSide, distortion);
    FoamPatch walls = mesh.patches.at(0);
    const int side = cellsPerSide * cellsPerSide;
    FoamPatch processor{"procBoundary0to1", PatchType::processor, walls.start, side};
    processor.neighbourRank = 1;
    walls.start += side;
    walls.size -= side;
    mesh.patches = {walls, processor};
    mesh.computeGeometry();
    return mesh;
}

/// A tetrahedron of cell (its first face's first edge).
int tetOf(const FoamLocator& locator, const FoamMesh& mesh, int cell) {
    return locator.tetIndex(cell, mesh.facesOf(cell)[0], 0);
}

TEST(ProcessorClearance, NoPointOfAProcessorFaceIsEverJudgedStayed) {
    const FoamMesh mesh = meshWithProcessorSide(testing::wavyDistortion);
    const FoamLocator locator(mesh);
    const ProcessorClearance clearance(mesh, locator, 1);
    const FoamPatch& processor = mesh.patches[1];
    std::mt19937_64 random(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Vec3> onFaces; // corners, point-averages and points inside the fanned triangles
    for (int face = processor.start; face < processor.start + processor.size; ++face) {
        const Vec3& middle = locator.faceMidpoint(face);
        onFaces.push_back(middle);
        const auto points = mesh.pointsOf(face);
        for (std::size_t k = 0; k < points.size(); ++k) {
            const Vec3& a = mesh.points[points[k]];
            const Vec3& b = mesh.points[points[(k + 1) % points.size()]];
            onFaces.push_back(a);
            double s = unit(random), t = unit(random);
            if (s + t > 1) s = 1 - s, t = 1 - t;
            onFaces.push_back(middle + s * (a - middle) + t * (b - middle));
        }
    }
    int stayedCells = 0;
    for (int cell = 0; cell < mesh.cellCount; ++cell) {
        const int tet = tetOf(locator, mesh, cell);
        for (const Vec3& point : onFaces) ASSERT_FALSE(clearance.stayed(tet, point)) << cell;
        stayedCells += clearance.stayed(tet, mesh.cellCentres[cell]);
    }
    // Not a check that cannot fail the other way: most cells lie well away from the patch.
    EXPECT_GT(stayedCells, mesh.cellCount / 2);
}

TEST(ProcessorClearance, EveryPointJudgedStayedIsOnThePartsSide) {
    // Undistorted, the processor faces fill the plane x = 0.
    const FoamMesh mesh = meshWithProcessorSide([](const Vec3& x) { return x; });
    const FoamLocator locator(mesh);
    const ProcessorClearance clearance(mesh, locator, 1);
    std::mt19937_64 random(11);
    std::normal_distribution<double> normal;
    const double h = 1.0 / cellsPerSide;
    for (int cell = 0; cell < mesh.cellCount; ++cell) {
        const int tet = tetOf(locator, mesh, cell);
        const Vec3& centre = mesh.cellCentres[cell];
        for (int k = 0; k < 200; ++k) {
            const Vec3 direction =
                Vec3(normal(random), normal(random), normal(random)).normalized();
            const Vec3 point = centre + (k % 20 + 1) * 0.1 * h * direction;
            if (clearance.stayed(tet, point)) ASSERT_GT(point.x(), 0.0) << cell;
        }
        // The nearest processor face's point-average lies straight across, at distance x: the
        // ball's radius is x less a face's reach, where that exceeds the cell's own (√3/2 h).
        const double reach = centre.x() - std::sqrt(2.0) / 2 * h;
        const Vec3 across(-1, 0, 0);
        if (reach > std::sqrt(3.0) / 2 * h) {
            EXPECT_TRUE(clearance.stayed(tet, centre + 0.99 * reach * across)) << cell;
            EXPECT_FALSE(clearance.stayed(tet, centre + 1.01 * reach * across)) << cell;
        } else {
            EXPECT_FALSE(clearance.stayed(tet, centre)) << cell;
        }
    }
}

} // namespace
} // namespace slides
