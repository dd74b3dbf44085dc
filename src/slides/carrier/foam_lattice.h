// FoamLattice: an OpenFOAM carrier's fields resampled once onto a structured lattice, for speed.
//
// Nodes origin + spacing (i a₀ + j a₁ + k a₂) (orthonormal directions a_d) fill a box over the
// mesh; a direction with one node is a plane (a wedge's centre plane, a 2-D mesh's mid plane).
// Each node holds U and the scalar fields as the exact path (locate, cellPoint) samples them, or
// is marked outside the mesh. A point in a lattice cell whose nodes are all inside is
// interpolated trilinearly (∇U: the derivative of the trilinear form, piecewise constant along
// each direction); for any other point, near or beyond the boundary, locate() says no and the
// caller takes the exact path, which also finds where a particle left the mesh.
//
//     carrier { type foamField; foamFieldCoeffs { interpolation lattice; latticeSpacing 2e-4; } }
#pragma once

#include "slides/carrier/gas_values.h"
#include "slides/core/vector.h"

#include <array>
#include <functional>
#include <optional>
#include <vector>

namespace slides {

struct LatticeFrame {
    Vec3 origin = Vec3::Zero();        ///< node (0, 0, 0)
    Mat3 axes = Mat3::Identity();      ///< columns: the orthonormal directions a₀, a₁, a₂
    std::array<int, 3> nodes{1, 1, 1}; ///< per direction, ≥ 1 (1: no extent that way)
    double spacing = 1;                ///< [m]
};

/// The 8 nodes of a point's lattice cell with their trilinear weights.
struct LatticeWeights {
    std::array<std::size_t, 8> node{};
    std::array<double, 8> weight{};
    std::array<Vec3, 8> gradient{}; ///< ∇ of each weight [1/m]
};

class FoamLattice {
public:
    /// The values at a point, nullopt outside the mesh.
    using Sampler = std::function<std::optional<GasValues>(const Vec3&)>;

    /// Samples every node, in order along a₀ first (so a walking sampler moves one node a call);
    /// keeps scalar s only where keepScalar[s] (memory: 24 bytes a node for U, 8 per scalar).
    FoamLattice(const LatticeFrame& frame, const Sampler& sample,
                std::array<bool, 3> keepScalar = {});

    /// The weights of point's lattice cell, or false when the point lies outside the lattice or
    /// its cell has a node outside the mesh. Coordinates along a one-node direction are ignored.
    bool locate(const Vec3& point, LatticeWeights& out) const;

    Vec3 velocity(const LatticeWeights& at) const;
    /// dU_i/dx_j of the trilinear form.
    Mat3 velocityGradient(const LatticeWeights& at) const;
    /// Scalar which (0 k, 1 ε, 2 T) at the point; zero when the lattice does not keep it.
    double scalar(int which, const LatticeWeights& at) const;

    const LatticeFrame& frame() const { return frame_; }
    std::size_t nodeCount() const { return velocity_.size(); }
    std::size_t nodesInside() const;

private:
    std::size_t nodeIndex(int i, int j, int k) const {
        return (static_cast<std::size_t>(k) * static_cast<std::size_t>(frame_.nodes[1]) +
                static_cast<std::size_t>(j)) *
                   static_cast<std::size_t>(frame_.nodes[0]) +
               static_cast<std::size_t>(i);
    }

    LatticeFrame frame_;
    std::vector<Vec3> velocity_;
    std::array<std::vector<double>, 3> scalars_;
    std::vector<char> inside_;     ///< per node
    std::vector<char> cellInside_; ///< per lattice cell (indexed by its lowest node): all 8 inside
};

} // namespace slides
