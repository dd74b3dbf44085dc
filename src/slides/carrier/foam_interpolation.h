// Interpolation of cell-centred OpenFOAM fields to points located by FoamLocator.
//
// cell: the value of the cell holding the point, and a gradient that is the volume average of
// the cellPoint gradients over the cell's tetrahedra. cellPoint (OpenFOAM's
// interpolationCellPoint): values at the mesh points from the surrounding cell values and the
// boundary face values, then linear (barycentric) within the tetrahedron; the gradient is the
// tetrahedron's constant gradient. Point values come from an inverse-distance-squared weighted
// least-squares linear fit about the point (OpenFOAM's volPointInterpolation averages with
// inverse-distance weights, which is not exact for a linear field; the fit is, on any mesh: a
// boundary point whose cells and faces do not fix a linear function adds the next cells).
// Boundary face values enter the fit beside the cells (volPointInterpolation gives boundary
// points their faces' values alone): a noSlip wall's zero pulls its points to U ≈ 0 (≤ 4e-4 m/s
// on the impingingJet plate against 25 m/s at the nozzle); giving the faces precedence by weight
// makes the fit ill-conditioned at edges of curved patches.
//
//     carrier { type foamField; foamFieldCoeffs { interpolation cellPoint; } }
#pragma once

#include "slides/carrier/foam_field.h"
#include "slides/carrier/foam_locator.h"
#include "slides/carrier/gas_values.h"

#include <array>
#include <span>
#include <string_view>
#include <vector>

namespace slides {

enum class FoamInterpolation { cell, cellPoint, lattice };

struct FoamInterpolationName {
    FoamInterpolation value;
    std::string_view name;
};

/// How to add a scheme: an enumerator, its name here, its case in FoamCarrier::sampleAt().
/// lattice: cellPoint resampled onto a structured lattice (carrier/foam_lattice.h).
inline constexpr std::array<FoamInterpolationName, 3> foamInterpolationNames() {
    return {{{FoamInterpolation::cell, "cell"},
             {FoamInterpolation::cellPoint, "cellPoint"},
             {FoamInterpolation::lattice, "lattice"}}};
}

/// Point weights of one mesh: point value p = Σ weight·sample, where a sample is a cell value
/// or a boundary face value (patches of type patch and wall; a patch without a value in the
/// field file contributes its owner cell's value, as zeroGradient; noSlip walls are zero).
class PointWeights {
public:
    explicit PointWeights(const FoamMesh& mesh);

    template <typename T> std::vector<T> pointValues(const FoamVolField<T>& field) const;

private:
    const FoamMesh& mesh_;
    std::vector<int> offsets_; ///< samples of point p: [offsets_[p], offsets_[p+1])
    std::vector<int> samples_; ///< cell index, or cellCount + face for a boundary face
    std::vector<double> weights_;
};

/// Weights α_k of the inverse-distance-squared least-squares linear fit at point over samples
/// at positions (the point value is Σ α_k φ_k, in this order); rankDeficient when the samples
/// do not fix a linear function, or nearly.
std::vector<double> pointFitWeights(const Vec3& point, std::span<const Vec3> positions,
                                    bool& rankDeficient);

/// One field ready to interpolate: cell values, point values, face point-average values.
template <typename T> struct InterpolableField {
    std::vector<T> cells;
    std::vector<T> points;
    std::vector<T> faceMidpoints;

    InterpolableField(const FoamVolField<T>& field, const FoamMesh& mesh,
                      const PointWeights& weights);

    /// Face point averages again, after point values changed (carrier/foam_shared_points.h).
    void refreshFaceMidpoints(const FoamMesh& mesh);
    /// The cellPoint value at a located point.
    T value(const FoamMesh& mesh, const TetLocation& at) const;
    /// The values at the four vertices of a located point's tetrahedron, in the order of
    /// at.weights: cell centre, face midpoint, the edge's two points.
    std::array<T, 4> vertexValues(const TetLocation& at) const {
        return {cells[at.cell], faceMidpoints[at.face], points[at.points[0]], points[at.points[1]]};
    }
};

/// The constant gradient of U in tetrahedron at (cellPoint): gradient(i, j) = dU_i/dx_j; T is
/// Vec3 (U alone) or GasValues.
template <typename T>
Mat3 tetGradient(const FoamMesh& mesh, const FoamLocator& locator,
                 const InterpolableField<T>& velocity, const TetLocation& at);

/// The constant gradient of U over tetrahedron at from U at its vertices (in the order of
/// InterpolableField::vertexValues).
Mat3 tetGradient(const FoamLocator& locator, const TetLocation& at,
                 const std::array<Vec3, 4>& vertexVelocities);

/// The gradient of each cell for the cell scheme: volume average of its tetrahedra's gradients.
template <typename T>
std::vector<Mat3> cellGradients(const FoamMesh& mesh, const FoamLocator& locator,
                                const InterpolableField<T>& velocity);

} // namespace slides
