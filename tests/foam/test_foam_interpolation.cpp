// ctest-labels: foam carrier
// Cell location and interpolation on OpenFOAM meshes: the walking locator against brute force,
// cellPoint exact for linear fields on polyhedral and curved meshes, convergence orders under
// refinement, and the axisymmetric wedge tracked in 3-D.
#include "../support/foam_test_mesh.h"
#include "slides/carrier/foam_carrier.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/carrier/foam_locator.h"
#include "slides/core/error.h"
#include "slides/core/name_table.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <random>

#include <unistd.h>

namespace slides {
namespace {

const std::filesystem::path data = std::filesystem::path(SLIDES_SOURCE_DIR) / "tests/foam/data";

/// The first cell holding point by testing every cell.
TetLocation bruteForce(const FoamLocator& locator, const FoamMesh& mesh, const Vec3& point) {
    for (int c = 0; c < mesh.cellCount; ++c)
        if (auto found = locator.locateInCell(point, c)) return *found;
    return {};
}

struct NamedMesh {
    std::string name;
    FoamMesh mesh;
};

std::vector<NamedMesh> testMeshes() {
    return {{"dualPolyhedral", readFoamMesh(data / "dualPolyhedral")},
            {"wavyHex", testing::hexBlockMesh(5, testing::wavyDistortion)}};
}

// Random points (1 % of them outside the mesh's box), walked to from a random start cell,
// land in the cell brute force finds; points outside are outside for both, and the walk names
// the patch it left through.
TEST(FoamLocator, AgreesWithBruteForceOnRandomPoints) {
    for (const auto& [name, mesh] : testMeshes()) {
        const FoamLocator locator(mesh);
        std::mt19937 random(7);
        const Vec3 margin = 0.01 * (mesh.boundsMax - mesh.boundsMin);
        std::uniform_real_distribution<double> unit(0, 1);
        std::uniform_int_distribution<int> anyCell(0, mesh.cellCount - 1);
        int inside = 0, outside = 0;
        for (int n = 0; n < 3000; ++n) {
            Vec3 point;
            for (int a = 0; a < 3; ++a)
                point[a] = mesh.boundsMin[a] - margin[a] +
                           unit(random) * (mesh.boundsMax[a] - mesh.boundsMin[a] + 2 * margin[a]);
            const TetLocation expected = bruteForce(locator, mesh, point);
            const TetLocation walked = locator.locate(point, anyCell(random));
            const TetLocation searched = locator.locate(point, -1);
            ASSERT_EQ(walked.found(), expected.found()) << name << " point " << point.transpose();
            ASSERT_EQ(searched.found(), expected.found()) << name;
            if (expected.found()) {
                ++inside;
                EXPECT_EQ(walked.cell, expected.cell) << name;
                EXPECT_EQ(searched.cell, expected.cell) << name;
            } else {
                ++outside;
                EXPECT_GE(walked.exitPatch, 0) << name << ": a walk that leaves names its patch";
            }
        }
        EXPECT_GT(inside, 1000) << name;
        EXPECT_GT(outside, 10) << name;
    }
}

// A mesh graded 1:91 toward one corner (x ↦ x³ per axis, 6³ cells), as the impinging jet's mesh is
// toward the nozzle: the search's bins, sized for one cell on average, hold dozens of cells
// there. Points drawn densely toward that corner are found in the cell brute force finds, by the
// search (a walk from the bin's nearest cell centre) and by walks from any cell.
TEST(FoamLocator, SearchFindsPointsWhereBinsHoldManyCells) {
    const FoamMesh mesh =
        testing::hexBlockMesh(6, [](const Vec3& x) { return Vec3(x.array().cube()); });
    const FoamLocator locator(mesh);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(0, 1);
    std::uniform_int_distribution<int> anyCell(0, mesh.cellCount - 1);
    for (int n = 0; n < 2000; ++n) {
        Vec3 point;
        for (int a = 0; a < 3; ++a) point[a] = std::pow(unit(random), 6.0); // dense near 0
        const TetLocation expected = bruteForce(locator, mesh, point);
        ASSERT_TRUE(expected.found()) << point.transpose();
        EXPECT_EQ(locator.locate(point, -1).cell, expected.cell) << point.transpose();
        EXPECT_EQ(locator.locate(point, anyCell(random)).cell, expected.cell) << point.transpose();
    }
}

// Points exactly on mesh points, edges, internal face centres and face point-averages are found
// (they lie on several cells' closures: any of them is right) from any start cell.
TEST(FoamLocator, FindsPointsOnFacesEdgesAndVertices) {
    for (const auto& [name, mesh] : testMeshes()) {
        const FoamLocator locator(mesh);
        std::vector<Vec3> points = mesh.points;
        for (int f = 0; f < mesh.faceCount(); ++f) {
            // A warped boundary face's centre may lie off its triangles, outside the mesh.
            if (f < mesh.internalFaceCount()) points.push_back(mesh.faceCentres[f]);
            points.push_back(locator.faceMidpoint(f));
            const auto ring = mesh.pointsOf(f);
            points.push_back(0.5 * (mesh.points[ring[0]] + mesh.points[ring[1]]));
        }
        std::mt19937 random(3);
        std::uniform_int_distribution<int> anyCell(0, mesh.cellCount - 1);
        for (const Vec3& point : points) {
            const TetLocation walked = locator.locate(point, anyCell(random));
            ASSERT_TRUE(walked.found()) << name << " point " << point.transpose();
            EXPECT_TRUE(locator.locateInCell(point, walked.cell).has_value());
            EXPECT_TRUE(bruteForce(locator, mesh, point).found());
        }
    }
}

// Every tetrahedron (cell, face, edge) of a cell has its own index below tetIndexEnd(), and the
// index gives it back: a particle's one int32 location names its tetrahedron.
TEST(FoamLocator, TetrahedronIndicesNameEachTetrahedronOnce) {
    for (const auto& [name, mesh] : testMeshes()) {
        const FoamLocator locator(mesh);
        std::vector<int> seen(static_cast<std::size_t>(locator.tetIndexEnd()), 0);
        for (int c = 0; c < mesh.cellCount; ++c)
            for (const int f : mesh.facesOf(c))
                for (int edge = 0; edge < static_cast<int>(mesh.pointsOf(f).size()); ++edge) {
                    const int tet = locator.tetIndex(c, f, edge);
                    ASSERT_GE(tet, 0) << name;
                    ASSERT_LT(tet, locator.tetIndexEnd()) << name;
                    ++seen[static_cast<std::size_t>(tet)];
                    const TetLocation back = locator.tetAt(tet);
                    EXPECT_EQ(back.cell, c) << name;
                    EXPECT_EQ(back.face, f) << name;
                    EXPECT_EQ(back.edge, edge) << name;
                    EXPECT_EQ(back.tet, tet) << name;
                }
        EXPECT_EQ(*std::max_element(seen.begin(), seen.end()), 1) << name;
    }
}

// Particles moving 0.3 cell a step, each walking from the tetrahedron of its previous point (as
// FoamCarrier keeps it): each lands in a tetrahedron whose weights hold the point (≥ −tolerance)
// and in a cell that holds it; a point still inside its previous tetrahedron (by a margin
// of 1e-6 in every weight) stays there, with that tetrahedron's barycentric weights.
TEST(FoamLocator, WalksFromThePreviousTetrahedron) {
    for (const auto& [name, mesh] : testMeshes()) {
        const FoamLocator locator(mesh);
        std::mt19937 random(5);
        std::uniform_real_distribution<double> unit(0, 1);
        const double cellSize =
            std::cbrt((mesh.boundsMax - mesh.boundsMin).prod() / mesh.cellCount);
        int stayed = 0, moved = 0;
        for (int particle = 0; particle < 100; ++particle) {
            Vec3 point = mesh.cellCentres[static_cast<std::size_t>(particle * 7 % mesh.cellCount)];
            TetLocation at = locator.locate(point, -1);
            ASSERT_TRUE(at.found()) << name;
            for (int step = 0; step < 40; ++step) {
                Vec3 direction(unit(random) - 0.5, unit(random) - 0.5, unit(random) - 0.5);
                const Vec3 next = point + 0.3 * cellSize * direction.normalized();
                const TetLocation expected = bruteForce(locator, mesh, next);
                if (!expected.found()) continue; // stay inside the mesh
                const TetLocation previous = locator.tetAt(at.tet);
                const auto before = barycentricWeights(
                    locator.vertices(previous.cell, previous.face, previous.edge), next);
                at = locator.locateFrom(next, at.tet);
                ASSERT_TRUE(at.found()) << name << " point " << next.transpose();
                EXPECT_TRUE(locator.locateInCell(next, at.cell).has_value()) << name;
                const auto weights =
                    barycentricWeights(locator.vertices(at.cell, at.face, at.edge), next);
                EXPECT_GE(*std::min_element(weights.begin(), weights.end()),
                          -FoamLocator::tolerance)
                    << name;
                if (*std::min_element(before.begin(), before.end()) > 1e-6) {
                    ++stayed;
                    EXPECT_EQ(at.tet, previous.tet) << name;
                    EXPECT_EQ(at.weights, before) << name;
                } else {
                    ++moved;
                }
                point = next;
            }
        }
        EXPECT_GT(stayed, 100) << name;
        EXPECT_GT(moved, 1000) << name;
    }
}

Mat3 linearGradient() {
    Mat3 gradient;
    gradient << 1.5, -2.0, 0.25, 0.5, 3.0, -1.0, -0.75, 2.5, 1.0;
    return gradient;
}

/// U = A x + b at cell centres, and at the face centres of patches that take a value.
FoamVolField<Vec3> linearField(const FoamMesh& mesh) {
    const Mat3 A = linearGradient();
    const Vec3 b(1, -2, 0.5);
    FoamVolField<Vec3> field;
    for (const Vec3& centre : mesh.cellCentres) field.cells.push_back(A * centre + b);
    field.patchValues.resize(mesh.patches.size());
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        const auto& patch = mesh.patches[p];
        if (patch.type != PatchType::patch && patch.type != PatchType::wall) continue;
        for (int f = patch.start; f < patch.start + patch.size; ++f)
            field.patchValues[p].push_back(A * mesh.faceCentres[f] + b);
    }
    return field;
}

// The requirement "a linear field is reproduced exactly by cellPoint on any mesh": values and
// the tetrahedron gradient at random points of the polyhedral dual mesh (symmetry patch
// without values included) and the curved hex mesh, to round-off (1e-11 of |U| ~ 1, 1e-8 of
// |∇U| ~ 3: a gradient divides by tetrahedron edges of ~0.01).
TEST(CellPointInterpolation, ReproducesLinearFieldsExactly) {
    for (const auto& [name, mesh] : testMeshes()) {
        const FoamLocator locator(mesh);
        const PointWeights weights(mesh);
        const InterpolableField<Vec3> field(linearField(mesh), mesh, weights);
        for (std::size_t p = 0; p < mesh.points.size(); ++p)
            ASSERT_LT(
                (field.points[p] - (linearGradient() * mesh.points[p] + Vec3(1, -2, 0.5))).norm(),
                1e-11)
                << name << " point " << p;
        std::mt19937 random(11);
        std::uniform_real_distribution<double> unit(0, 1);
        int checked = 0;
        while (checked < 500) {
            const Vec3 point = mesh.boundsMin + Vec3(unit(random), unit(random), unit(random))
                                                    .cwiseProduct(mesh.boundsMax - mesh.boundsMin);
            const TetLocation at = locator.locate(point, -1);
            if (!at.found()) continue;
            ++checked;
            const Vec3 exact = linearGradient() * point + Vec3(1, -2, 0.5);
            EXPECT_LT((field.value(mesh, at) - exact).norm(), 1e-11) << name;
            EXPECT_LT((tetGradient(mesh, locator, field, at) - linearGradient()).norm(), 1e-8)
                << name;
        }
        const auto cellGradient = cellGradients(mesh, locator, field);
        for (const Mat3& gradient : cellGradient)
            EXPECT_LT((gradient - linearGradient()).norm(), 1e-8);
    }
}

double smoothField(const Vec3& x) {
    return std::sin(2 * x.x()) * std::cos(3 * x.y()) * std::exp(x.z());
}

/// Largest interpolation error of smoothField over fixed random points of the curved hex mesh.
double maximumError(int cellsPerSide, FoamInterpolation scheme) {
    const FoamMesh mesh = testing::hexBlockMesh(cellsPerSide, testing::wavyDistortion);
    FoamVolField<double> field;
    for (const Vec3& centre : mesh.cellCentres) field.cells.push_back(smoothField(centre));
    field.patchValues.resize(1);
    for (int f = mesh.patches[0].start; f < mesh.faceCount(); ++f)
        field.patchValues[0].push_back(smoothField(mesh.faceCentres[f]));
    const FoamLocator locator(mesh);
    const InterpolableField<double> interpolable(field, mesh, PointWeights(mesh));
    std::mt19937 random(5);
    double error = 0;
    std::uniform_real_distribution<double> inner(0.03, 0.97); // off the curved boundary
    for (int n = 0; n < 4000; ++n) {
        const Vec3 point =
            testing::wavyDistortion(Vec3(inner(random), inner(random), inner(random)));
        const TetLocation at = locator.locate(point, -1);
        EXPECT_TRUE(at.found());
        const double value = scheme == FoamInterpolation::cell ? interpolable.cells[at.cell]
                                                               : interpolable.value(mesh, at);
        error = std::max(error, std::abs(value - smoothField(point)));
    }
    return error;
}

// Orders of accuracy under refinement h → h/2 → h/4 on the curved hex mesh: cellPoint is linear
// within tetrahedra, so its maximum error falls as h² (measured ≈ 2); the cell value is
// piecewise constant, error ∝ h (measured 0.95 then 0.84: the largest distance from a
// cell centre shrinks unevenly on the curved cells). The bounds leave room for the
// pre-asymptotic range of these coarse meshes (6³ to 24³ cells).
TEST(FoamInterpolation, ConvergesAtTheExpectedOrder) {
    for (const auto scheme : {FoamInterpolation::cellPoint, FoamInterpolation::cell}) {
        const double coarse = maximumError(6, scheme), medium = maximumError(12, scheme),
                     fine = maximumError(24, scheme);
        const double order1 = std::log2(coarse / medium), order2 = std::log2(medium / fine);
        std::printf("%s: max errors %.3e %.3e %.3e, orders %.2f %.2f\n",
                    std::string(nameOf(foamInterpolationNames(), scheme)).c_str(), coarse, medium,
                    fine, order1, order2);
        if (scheme == FoamInterpolation::cellPoint) {
            EXPECT_GT(order2, 1.8);
            EXPECT_LT(order2, 2.3);
        } else {
            EXPECT_GT(order2, 0.75);
            EXPECT_LT(order2, 1.25);
        }
    }
}

/// Writes an ASCII volVectorField: cells and the patches of type patch/wall hold values.
void writeVectorField(const std::filesystem::path& file, const FoamMesh& mesh,
                      const FoamVolField<Vec3>& field) {
    std::ofstream out(file);
    out.precision(17);
    out << "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
        << "dimensions [0 1 -1 0 0 0 0];\ninternalField nonuniform List<vector> "
        << field.cells.size() << "(\n";
    for (const Vec3& value : field.cells) out << "(" << value.transpose() << ")\n";
    out << ");\nboundaryField\n{\n";
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        out << mesh.patches[p].name << " { type ";
        if (field.patchValues[p].empty()) {
            out << (mesh.patches[p].type == PatchType::wedge ? "wedge" : "empty") << "; }\n";
            continue;
        }
        out << "fixedValue; value nonuniform List<vector> " << field.patchValues[p].size() << "(";
        for (const Vec3& value : field.patchValues[p]) out << "(" << value.transpose() << ")";
        out << "); }\n";
    }
    out << "}\n";
}

// The 5° wedge about the x axis (tests/foam/data/wedge) carries U = (1 + 2x, 3y, 3z) written at
// its cells and faces: axisymmetric and linear in 3-D. Sampled at random 3-D points of the
// swept volume, U and ∇U = diag(2, 3, 3) come back rotated to the point, exact to round-off:
// the u_r = 3r profile is linear within the wedge, and the hoop term u_r/r = 3 restores ∂u_z/∂z.
// The same with the lattice scheme: on the wedge's centre plane (one node across) the bilinear
// lattice is exact for the linear field too, and describe() reports its error.
TEST(WedgeCarrier, SamplesTheRotatedSolutionIn3D) {
    const auto directory =
        std::filesystem::temp_directory_path() / ("slides_wedge_" + std::to_string(::getpid()));
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory / "0");
    std::filesystem::copy(data / "wedge" / "constant", directory / "constant",
                          std::filesystem::copy_options::recursive);
    const FoamMesh mesh = readFoamMesh(directory);
    const auto linear = [](const Vec3& x) { return Vec3(1 + 2 * x.x(), 3 * x.y(), 3 * x.z()); };
    FoamVolField<Vec3> field;
    for (const Vec3& centre : mesh.cellCentres) field.cells.push_back(linear(centre));
    field.patchValues.resize(mesh.patches.size());
    for (std::size_t p = 0; p < mesh.patches.size(); ++p)
        if (mesh.patches[p].type == PatchType::patch || mesh.patches[p].type == PatchType::wall)
            for (int f = mesh.patches[p].start; f < mesh.patches[p].start + mesh.patches[p].size;
                 ++f)
                field.patchValues[p].push_back(linear(mesh.faceCentres[f]));
    writeVectorField(directory / "0" / "U", mesh, field);

    FoamCarrierSettings lattice;
    lattice.interpolation = FoamInterpolation::lattice;
    lattice.latticeSpacing = 0.004;
    const FoamCarrier latticeCarrier(directory, lattice);
    ASSERT_NE(latticeCarrier.lattice(), nullptr);
    EXPECT_EQ(latticeCarrier.lattice()->frame().nodes[2], 1) << "the wedge's centre plane";
    EXPECT_NE(latticeCarrier.describe().find("against cellPoint"), std::string::npos);
    FoamCarrierSettings tooFine = lattice;
    tooFine.latticeSpacing = 1e-7; // 1e6 × 5e5 nodes: refused before allocating them
    EXPECT_THROW(FoamCarrier(directory, tooFine), InputError);
    const FoamCarrier carrier(directory, {});
    ASSERT_TRUE(carrier.wedge().has_value());
    EXPECT_LT((carrier.wedge()->axis.cross(Vec3::UnitX())).norm(), 1e-12);
    EXPECT_LT(carrier.wedge()->origin.norm(), 1e-12);
    std::mt19937 random(13);
    std::uniform_real_distribution<double> unit(0, 1);
    std::vector<Vec3> points;
    for (int n = 0; n < 400; ++n) {
        const double angle = 2 * std::acos(-1.0) * unit(random), radius = 0.049 * unit(random);
        points.emplace_back(0.1 * unit(random), radius * std::cos(angle), radius * std::sin(angle));
    }
    CarrierSample sample;
    const Mat3 gradient = Vec3(2, 3, 3).asDiagonal();
    for (const FoamCarrier* scheme : {&carrier, &latticeCarrier}) {
        scheme->sample(points, 0.0, CarrierNeeds{true, false, false}, sample);
        for (std::size_t i = 0; i < points.size(); ++i) {
            EXPECT_LT((sample.velocity[i] - linear(points[i])).norm(), 1e-12)
                << points[i].transpose();
            EXPECT_LT((sample.velocityGradient[i] - gradient).norm(), 1e-8)
                << points[i].transpose();
        }
    }
    // Beyond the outer radius: outside, still gas, and the walk names the wall it crossed.
    std::vector<std::int32_t> location{-1};
    carrier.sampleFrom(std::vector<Vec3>{Vec3(0.05, 0.0, 0.04)}, location, 0.0, {}, sample);
    EXPECT_GE(location[0], 0);
    carrier.sampleFrom(std::vector<Vec3>{Vec3(0.05, 0.0, 0.06)}, location, 0.0, {}, sample);
    EXPECT_EQ(sample.velocity[0], Vec3::Zero());
    EXPECT_EQ(-3 - location[0], 2) << "left through patch 2, outer";
    std::filesystem::remove_all(directory);
}

} // namespace
} // namespace slides
