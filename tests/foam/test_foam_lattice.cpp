// ctest-labels: foam carrier
// The lattice scheme (carrier/foam_lattice.h): cellPoint resampled onto a structured lattice,
// then trilinear. Trilinear interpolation reproduces linear fields exactly, and its error for a
// smooth field is ½ Σ_d ∂²u/∂x_d² t_d(1 − t_d) h² + O(h³): second order in the spacing h.
#include "../support/foam_test_mesh.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/carrier/foam_lattice.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

namespace slides {
namespace {

/// A lattice of the given spacing over mesh's box, its nodes sampled by cellPoint from field.
struct LatticeOnMesh {
    FoamMesh mesh;
    FoamLocator locator;
    InterpolableField<Vec3> field;
    FoamLattice lattice;

    LatticeOnMesh(FoamMesh meshIn, const std::function<Vec3(const Vec3&)>& u, double spacing)
        : mesh(std::move(meshIn)), locator(mesh), field(sampled(mesh, u), mesh, PointWeights(mesh)),
          lattice(frameOver(mesh, spacing), [this](const Vec3& x) { return exact(x); }) {}

    std::optional<GasValues> exact(const Vec3& x) const {
        const TetLocation at = locator.locate(x, -1);
        if (!at.found()) return std::nullopt;
        return GasValues{field.value(mesh, at), {}};
    }

    static FoamVolField<Vec3> sampled(const FoamMesh& mesh,
                                      const std::function<Vec3(const Vec3&)>& u) {
        FoamVolField<Vec3> values;
        for (const Vec3& centre : mesh.cellCentres) values.cells.push_back(u(centre));
        values.patchValues.resize(1); // the one wall patch, at its face centres
        for (int f = mesh.patches[0].start; f < mesh.faceCount(); ++f)
            values.patchValues[0].push_back(u(mesh.faceCentres[f]));
        return values;
    }

    static LatticeFrame frameOver(const FoamMesh& mesh, double spacing) {
        LatticeFrame frame;
        frame.origin = mesh.boundsMin;
        frame.spacing = spacing;
        for (int d = 0; d < 3; ++d)
            frame.nodes[d] = 1 + static_cast<int>(std::ceil(
                                     (mesh.boundsMax[d] - mesh.boundsMin[d]) / spacing - 1e-9));
        return frame;
    }
};

Vec3 identity(const Vec3& x) { return x; }

// A linear U = A x + b, sampled by cellPoint (exact for it) on the curved hex mesh, comes back
// from the lattice exactly wherever the lattice serves a point (round-off: 1e-12 of |U| ~ 3; the
// gradient divides by the spacing, 1e-10), and its trilinear gradient is A.
TEST(FoamLattice, ReproducesLinearFieldsExactly) {
    Mat3 A;
    A << 1.5, -2.0, 0.25, 0.5, 3.0, -1.0, -0.75, 2.5, 1.0;
    const Vec3 b(1, -2, 0.5);
    const LatticeOnMesh setup(
        testing::hexBlockMesh(8, testing::wavyDistortion),
        [&](const Vec3& x) { return Vec3(A * x + b); }, 0.05);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0, 1);
    int served = 0;
    for (int n = 0; n < 2000; ++n) {
        const Vec3 x = testing::wavyDistortion(Vec3(unit(random), unit(random), unit(random)));
        LatticeWeights weights;
        if (!setup.lattice.locate(x, weights)) continue;
        ++served;
        EXPECT_LT((setup.lattice.velocity(weights) - (A * x + b)).norm(), 1e-12);
        EXPECT_LT((setup.lattice.velocityGradient(weights) - A).norm(), 1e-10);
    }
    // Cells touching a node outside the curved boundary are not served: most inner ones are.
    EXPECT_GT(served, 1400);
    EXPECT_LT(setup.lattice.nodesInside(), setup.lattice.nodeCount());
}

/// The largest |lattice − cellPoint| over fixed random points of the unit cube (40³ cells).
double latticeError(double spacing) {
    const auto u = [](const Vec3& x) {
        return Vec3(std::sin(2 * x.x()) * std::cos(3 * x.y()), std::exp(x.z()) * x.x(), 1.0);
    };
    static const FoamMesh mesh = testing::hexBlockMesh(40, identity);
    const LatticeOnMesh setup(mesh, u, spacing);
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(0, 1);
    double worst = 0;
    for (int n = 0; n < 3000; ++n) {
        const Vec3 x(unit(random), unit(random), unit(random));
        LatticeWeights weights;
        EXPECT_TRUE(setup.lattice.locate(x, weights)) << "every node of the cube is in the mesh";
        worst =
            std::max(worst, (setup.lattice.velocity(weights) - setup.exact(x)->velocity).norm());
    }
    return worst;
}

// Error against cellPoint under lattice refinement h = 1/4 → 1/8 → 1/16 of the cube: order 2
// (the bounds leave room for the cellPoint field's own kinks at the 1/40 mesh, which the finest
// lattice starts to see).
TEST(FoamLattice, ErrorFallsAsTheSpacingSquared) {
    const double coarse = latticeError(0.25), medium = latticeError(0.125),
                 fine = latticeError(0.0625);
    const double order1 = std::log2(coarse / medium), order2 = std::log2(medium / fine);
    std::printf("lattice: max errors %.3e %.3e %.3e, orders %.2f %.2f\n", coarse, medium, fine,
                order1, order2);
    EXPECT_GT(order1, 1.8);
    EXPECT_LT(order1, 2.3);
    EXPECT_GT(order2, 1.7);
    EXPECT_LT(order2, 2.3);
}

} // namespace
} // namespace slides
