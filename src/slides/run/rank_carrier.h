// RankCarrier: the gas of a decomposed OpenFOAM case, each rank holding its processor<rank>/
// part, sampled anywhere in the whole mesh.
//
// Reference: OpenFOAM v1912 decomposePar / processorPolyPatch (the parts and the faces they
// share). A batch is sampled on this rank's part first (carrier/foam_carrier.h); the points it
// does not hold (a midpoint across a processor patch, a pilot path, the carrier lattice) are
// gathered from every rank, each rank locates them in its part, the lowest rank holding a point
// samples it, and the values reach every rank by one sum (the other ranks add zeros, so the sum
// is exact). A location is this rank's tetrahedron; for a point another rank holds, one past the
// part's tetrahedra plus its index in the batch's remote points (so resolutionLength() answers
// for it until the next batch), −1 when that does not fit an int32; ≤ −2 outside the whole mesh
// (through a patch of the case, never a processor patch). Every call is collective: every rank
// makes the same calls in the same order (the stepper's stages, the scene analysis' pilots, the
// checks), with its own points. Only 3-D meshes with cell or cellPoint interpolation are supported
// in parallel so far.
//
//     mpirun -np 2 slides-track CASE -parallel     // carrier { type foamField; ... }
#pragma once

#include "slides/carrier/foam_carrier.h"
#include "slides/run/rank_communicator.h"

#include <filesystem>
#include <memory>

namespace slides {

class RankCarrier : public CarrierField {
public:
    /// This rank's part of the case in caseDirectory (processor<rank>/), read with settings;
    /// every rank checks the decomposition and its part, and all agree on any InputError.
    RankCarrier(const std::filesystem::path& caseDirectory, const FoamCarrierSettings& settings,
                const RankCommunicator& ranks);

    void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                CarrierSample& out) const override;
    bool keepsLocations() const override { return true; }
    void sampleFrom(std::span<const Vec3> points, std::span<std::int32_t> locations, double time,
                    CarrierNeeds needs, CarrierSample& out) const override;
    CarrierNeeds provides() const override { return part_->provides(); }
    bool steady() const override { return part_->steady(); }
    void holdInterval(double start, double end) const override { part_->holdInterval(start, end); }
    double resolutionLength(std::int32_t location) const override;
    /// The patches of the case (the processor patches left out), by index.
    std::vector<std::string> boundaryNames() const override { return boundaryNames_; }
    /// Patch name's faces on every rank, in rank order.
    std::vector<PatchTriangle> patchTriangles(const std::string& name) const override;
    /// This rank's triangles' tetrahedra, heldElsewhere for the other ranks' (collective).
    std::vector<std::int32_t> patchTriangleLocations(const std::string& name) const override;
    /// The lowest rank whose part holds a point keeps it, by one minimum over the ranks.
    void keepHeldHere(std::span<const Vec3> points, std::span<std::int32_t> locations,
                      std::vector<std::uint8_t>& keep) const override;
    std::optional<Box> bounds() const override { return bounds_; }
    /// A wedge's frame and a 2-D mesh's plane, as every part finds them (each from its own
    /// faces of the wedge or empty patches: the same to round-off).
    std::optional<AxisymmetricFrame> axisymmetry() const override { return part_->axisymmetry(); }
    std::optional<Vec3> planeNormal() const override { return part_->planeNormal(); }
    std::string describe() const override { return description_; }

    /// This rank's part.
    const FoamCarrier& part() const { return *part_; }
    const RankCommunicator& ranks() const { return ranks_; }
    /// Patches of index ≥ this are processor patches.
    int firstProcessorPatch() const { return static_cast<int>(boundaryNames_.size()); }

private:
    /// Whether this rank's part has a face of patch name.
    bool holdsPatch(const std::string& name) const;

    std::filesystem::path caseDirectory_;
    RankCommunicator ranks_;
    std::unique_ptr<FoamCarrier> part_;
    std::vector<std::string> boundaryNames_;
    Box bounds_;
    std::string description_;
    /// Resolution lengths of the last batch's points held by other ranks: such a point's
    /// location is the part's tetIndexEnd() + its index here (−1 past the int32 range).
    mutable std::vector<double> remoteResolution_;
};

} // namespace slides
