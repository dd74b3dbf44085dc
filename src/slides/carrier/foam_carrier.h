// FoamCarrier: the gas field of an OpenFOAM case (U; k, ε and T when present) at particles.
//
// Reads constant/polyMesh and the fields of one time directory (carrier/foam_mesh.h,
// carrier/foam_field.h), locates each point (carrier/foam_locator.h) once per batch, then
// interpolates every field with the same weights (carrier/foam_interpolation.h), as preCICE
// computes a mapping once and applies it to each field. A wedge mesh (axisymmetric case) is
// tracked in 3-D: a point maps to the wedge's centre plane by its axial coordinate and radius,
// and the sampled U and ∇U are rotated back about the axis (∇U with its hoop column u_r/r,
// which a wedge one cell thick cannot resolve). A 2-D mesh (empty patches) is
// sampled on its mid plane. A location (sampleFrom) is the locator's tetrahedron index, so each
// particle's walk starts in the tetrahedron where its last one ended. Points outside the mesh see
// still gas; sampleFrom marks them with the patch they left through, and the stepper counts them as
// escaped. With the lattice scheme the fields are resampled at start-up (carrier/foam_lattice.h) on
// the mapped 3-D, wedge or 2-D coordinates; points the lattice cannot serve take the exact
// cellPoint path, and describe() reports the lattice's error against cellPoint at random points of
// the mesh. With a time series (carrier/foam_series.h, cellPoint only) each point is located
// once and sampled on the two levels around the batch's time: U, ∇U, k, ε, T linear in time,
// ∂U/∂t their difference over the write interval.
//
//     carrier { type foamField; foamFieldCoeffs { time latestTime; interpolation cellPoint; } }
#pragma once

#include "slides/carrier/carrier_field.h"
#include "slides/carrier/foam_interpolation.h"
#include "slides/carrier/foam_lattice.h"
#include "slides/carrier/foam_series.h"
#include "slides/carrier/foam_shared_points.h"

#include <memory>
#include <optional>

namespace slides {

struct FoamCarrierSettings {
    std::string time = "latestTime"; ///< time directory: latestTime or a time value
    FoamInterpolation interpolation = FoamInterpolation::cellPoint;
    double latticeSpacing = 0; ///< lattice scheme: node spacing [m], 0: largest extent / 100
    std::optional<FoamSeriesSettings> series; ///< a time series instead of one time directory
};

/// A wedge's axis and centre plane: maps 3-D points to the wedge and rotates results back.
struct WedgeFrame {
    Vec3 origin = Vec3::Zero(); ///< a point on the axis
    Vec3 axis = Vec3::UnitX();
    Vec3 radial = Vec3::UnitY(); ///< in the centre plane, away from the axis into the mesh
    double angle = 0;            ///< the wedge's opening [rad]

    /// The point of the centre plane with x's axial coordinate and radius, and the rotation
    /// about the axis that takes that point back to x.
    Vec3 toWedge(const Vec3& x, Mat3& rotation) const;
};

class FoamCarrier : public CarrierField {
public:
    FoamCarrier(const std::filesystem::path& caseDirectory, FoamCarrierSettings settings);

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override;
    bool keepsLocations() const override { return true; }
    void sampleFrom(std::span<const Vec3> points, std::span<std::int32_t> locations, double time,
                    CarrierNeeds needs, CarrierSample& out) const override;
    std::string describe() const override;
    CarrierNeeds provides() const override;
    bool steady() const override { return !series_; }
    void holdInterval(double start, double end) const override;
    /// The time series, null for a frozen field.
    const FoamSeries* series() const { return series_.get(); }
    /// The size of location's cell: 6V/A of its faces in 3-D, 4V/A of the faces not on wedge or
    /// empty patches for a wedge or 2-D mesh; the lattice's spacing for the lattice scheme.
    double resolutionLength(std::int32_t location) const override;

    const FoamMesh& mesh() const { return mesh_; }
    const FoamLocator& locator() const { return *locator_; }
    const std::optional<WedgeFrame>& wedge() const { return wedge_; }
    /// A part of a decomposed case: the values at points of its processor patches fitted over
    /// every part's samples (carrier/foam_shared_points.h). Collective over the parts; once.
    void shareProcessorPoints(const PartAddressing& addressing, const PartAllGather& allGather);
    /// The lattice scheme's lattice, null for the other schemes.
    const FoamLattice* lattice() const { return lattice_.get(); }
    /// Box of the 3-D region the carrier covers (the wedge swept about its axis).
    std::optional<Box> bounds() const override;
    std::optional<Vec3> planeNormal() const override { return emptyNormal_; }
    std::optional<AxisymmetricFrame> axisymmetry() const override;
    /// The point of the mesh that stands for the 3-D point: on a wedge, the centre plane's point
    /// at its axial position and radius (rotation: the turn that takes it back to the point); on
    /// a 2-D mesh, its projection on the cell centres' plane; else the point itself.
    Vec3 meshPoint(const Vec3& point, Mat3& rotation) const;
    Vec3 meshPoint(const Vec3& point) const {
        Mat3 rotation;
        return meshPoint(point, rotation);
    }
    std::vector<std::string> boundaryNames() const override;
    std::vector<PatchTriangle> patchTriangles(const std::string& name) const override;
    std::vector<std::int32_t> patchTriangleLocations(const std::string& name) const override;
    /// Lattice scheme: latticeSpacing [m], latticeErrorMax and latticeErrorRms (|ΔU|/U_ref against
    /// cellPoint), latticeErrorPoints, latticeExactPathPoints (random points it does not serve).
    std::vector<std::pair<std::string, double>> figures() const override { return latticeFigures_; }

private:
    const FoamPatch& patchNamed(const std::string& name) const;
    /// levels: the series' levels around the batch's time, null for a frozen field.
    void sampleAt(const Vec3& point, std::int32_t& location, CarrierNeeds needs, CarrierSample& out,
                  std::size_t index, const LevelCache<FoamLevel>::Pair* levels) const;
    /// U, ∇U, ∂U/∂t, k, ε, T at a located point, linear in time between two levels.
    void sampleLevelsAt(const TetLocation& at, const Vec3& x, const Mat3& rotation,
                        const LevelCache<FoamLevel>::Pair& levels, CarrierNeeds needs,
                        CarrierSample& out, std::size_t i) const;
    /// The gradient at wedge point x with the hoop column of an axisymmetric field.
    Mat3 wedgeHoopGradient(const Mat3& gradient, const Vec3& velocity, const Vec3& x) const;
    [[noreturn]] void missing(const std::string& field) const;
    /// The lattice over the region points map to: the mesh box, or a wedge's or 2-D mesh's
    /// plane; and its error against cellPoint, for describe().
    void buildLattice(const std::filesystem::path& caseDirectory);
    /// The point's values by the exact path (locate, cellPoint), nullopt outside the mesh.
    std::optional<GasValues> cellPointValues(const Vec3& x, int& tet) const;

    std::filesystem::path timeDirectory_;
    FoamCarrierSettings settings_;
    FoamMesh mesh_;
    std::unique_ptr<FoamLocator> locator_;
    std::optional<WedgeFrame> wedge_;
    std::optional<Vec3> emptyNormal_; ///< 2-D mesh: sampled on the plane of the cell centres
    /// U, k, ε, T side by side per cell, face and point: a sample loads four records.
    std::unique_ptr<InterpolableField<GasValues>> gas_;
    std::array<bool, 3> hasScalar_{}; ///< k, ε, T given in the time directory
    std::vector<Mat3> cellGradients_; ///< cell scheme only
    /// A part of a decomposed case: the fields as read, until shareProcessorPoints() has used
    /// their boundary values.
    std::optional<FoamVolField<GasValues>> gasRead_;
    std::unique_ptr<FoamLattice> lattice_; ///< lattice scheme only
    std::string latticeReport_;
    std::vector<std::pair<std::string, double>> latticeFigures_;
    std::unique_ptr<FoamSeries> series_; ///< a time series: the levels replace the fields above
};

} // namespace slides
