// CarrierField: the carrier gas seen by the particles, sampled per batch of points.
//
// The one runtime-polymorphic boundary of the tracker (DESIGN.md): it is called once per batch,
// never per particle, so the particle loops stay inlinable. Implementations: the analytic jets
// (carrier/analytic_jet.h, carrier/round_laminar_jet.h) and OpenFOAM fields
// (carrier/foam_carrier.h), which keep each particle's tetrahedron between batches (sampleFrom).
//
//     carrier { type analyticJet; analyticJetCoeffs { ... } }
#pragma once

#include "slides/core/box.h"
#include "slides/core/vector.h"

#include <array>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace slides {

/// What a caller needs from a sample; a carrier fills only what is asked for.
struct CarrierNeeds {
    bool velocityGradient = false;  ///< ∇U: fluid acceleration, lift
    bool turbulence = false;        ///< k and ε: turbulent eddy sampling
    bool temperature = false;       ///< T: convective heating
    bool timeDerivative = false;    ///< ∂U/∂t: DU/Dt of an unsteady carrier (never of a steady)
    bool velocityLaplacian = false; ///< ∇²U: Faxén terms (physics/faxen.h)
};

/// One batch of samples, one entry per point, in the order of the points (structure of arrays).
struct CarrierSample {
    std::vector<Vec3> velocity;         ///< U [m/s]
    std::vector<Mat3> velocityGradient; ///< dU_i/dx_j [1/s], filled when needs.velocityGradient
    std::vector<double> turbulentKineticEnergy; ///< k [m²/s²], filled when needs.turbulence
    std::vector<double> dissipationRate;        ///< ε [m²/s³], filled when needs.turbulence
    std::vector<double> temperature;            ///< T [K], filled when needs.temperature
    std::vector<Vec3> velocityTimeDerivative;   ///< ∂U/∂t [m/s²], when needs.timeDerivative
    std::vector<Vec3> velocityLaplacian;        ///< ∇²U [1/(m s)], when needs.velocityLaplacian

    void resize(std::size_t count, CarrierNeeds needs) {
        velocity.resize(count);
        velocityGradient.resize(needs.velocityGradient ? count : 0);
        turbulentKineticEnergy.resize(needs.turbulence ? count : 0);
        dissipationRate.resize(needs.turbulence ? count : 0);
        temperature.resize(needs.temperature ? count : 0);
        velocityTimeDerivative.resize(needs.timeDerivative ? count : 0);
        velocityLaplacian.resize(needs.velocityLaplacian ? count : 0);
    }

    /// Entry i becomes entry j of `from`, in every field both samples hold.
    void copyEntry(std::size_t i, const CarrierSample& from, std::size_t j) {
        const auto copy = [&](auto& to, const auto& source) {
            if (!to.empty() && !source.empty()) to[i] = source[j];
        };
        copy(velocity, from.velocity);
        copy(velocityGradient, from.velocityGradient);
        copy(turbulentKineticEnergy, from.turbulentKineticEnergy);
        copy(dissipationRate, from.dissipationRate);
        copy(temperature, from.temperature);
        copy(velocityTimeDerivative, from.velocityTimeDerivative);
        copy(velocityLaplacian, from.velocityLaplacian);
    }
};

/// A triangle of a boundary patch.
using PatchTriangle = std::array<Vec3, 3>;

/// The frame of an axisymmetric field given on a wedge (OpenFOAM's axisymmetric meshes): the
/// field in 3-D is its centre plane's, spanned by axis and radial through origin, turned about
/// the axis.
struct AxisymmetricFrame {
    Vec3 origin = Vec3::Zero();  ///< a point on the axis
    Vec3 axis = Vec3::UnitX();   ///< unit
    Vec3 radial = Vec3::UnitY(); ///< unit, in the centre plane, away from the axis into the wedge
    double wedgeAngle = 0;       ///< the wedge's opening θ [rad]
};

class CarrierField {
public:
    virtual ~CarrierField() = default;

    /// Gas state at each point at time t. out is resized to points.size().
    virtual void sample(std::span<const Vec3> points, double time, CarrierNeeds needs,
                        CarrierSample& out) const = 0;

    /// Whether the carrier keeps a location per point between batches (a mesh tetrahedron): then
    /// the caller holds one int32 per particle, −1 when unknown, and samples with sampleFrom.
    virtual bool keepsLocations() const { return false; }

    /// sample() starting each point's search at locations[i] and updating it: ≥ 0 where it is, −1
    /// if unknown, or ≤ −2 for a point outside the mesh (−3 − location: the patch it left through,
    /// −1 when not known).
    virtual void sampleFrom(std::span<const Vec3> points, std::span<std::int32_t> locations,
                            double time, CarrierNeeds needs, CarrierSample& out) const {
        (void)locations;
        sample(points, time, needs, out);
    }

    /// Whether the field is frozen in time: then sample() ignores t and ∂U/∂t = 0, and callers
    /// neither ask for ∂U/∂t nor hold it. An unsteady carrier fills ∂U/∂t when asked.
    virtual bool steady() const { return true; }

    /// Makes an unsteady carrier ready to be sampled at times in [start, end] (a time series
    /// holds the levels around them): called between batches, never during one.
    virtual void holdInterval(double start, double end) const {
        (void)start;
        (void)end;
    }

    /// The optional fields the carrier can fill (the velocity and its gradient it always can).
    virtual CarrierNeeds provides() const { return {.velocityGradient = true}; }

    /// The length over which the interpolated field changes form near a location (a mesh
    /// cell's size, a lattice's spacing) [m]: a step should cross few of them. Infinite for a
    /// smooth analytic field.
    virtual double resolutionLength(std::int32_t location) const {
        (void)location;
        return std::numeric_limits<double>::infinity();
    }

    /// Figures the carrier reports about itself for the run summary (name, value), e.g. the
    /// lattice scheme's error against cellPoint.
    virtual std::vector<std::pair<std::string, double>> figures() const { return {}; }

    /// Names of the boundary patches a point can leave through, by index (location −3 − index).
    virtual std::vector<std::string> boundaryNames() const { return {}; }

    /// The faces of boundary patch `name` as triangles, each with its vertices counter-clockwise
    /// seen from the gas (surfaces of type patch, surfaces/patch_wall.h, on a 3-D mesh; patch
    /// injectors, integrate/patch_sampler.h, also on a wedge or 2-D mesh, where they are the
    /// wedge's or the slab's faces); the scene reader has checked that the mesh holds the patch.
    virtual std::vector<PatchTriangle> patchTriangles(const std::string& name) const {
        throw std::logic_error("carrier " + describe() + " has no patch " + name);
    }

    /// A location meaning that another rank's part of the mesh holds the point.
    static constexpr std::int32_t heldElsewhere = std::numeric_limits<std::int32_t>::max();

    /// The location of the tetrahedron behind each triangle of patchTriangles(name), in its
    /// order (a point drawn just into the gas from a triangle lies in it, so the injector needs
    /// no search), or heldElsewhere where another rank's part holds the triangle; empty when the
    /// carrier keeps no locations.
    virtual std::vector<std::int32_t> patchTriangleLocations(const std::string& name) const {
        (void)name;
        return {};
    }

    /// Of points given alike to every rank, those this rank keeps: each is kept on exactly one
    /// rank, the lowest whose part holds it (rank 0 when none does). A location of −1 is searched
    /// for here, heldElsewhere is not held here, any other is held here; a kept point's location
    /// is its tetrahedron here (−1 when no rank holds it). Collective on a decomposed mesh; one
    /// process keeps every point and leaves its locations.
    virtual void keepHeldHere(std::span<const Vec3> points, std::span<std::int32_t> locations,
                              std::vector<std::uint8_t>& keep) const {
        (void)locations;
        keep.assign(points.size(), 1);
    }

    /// The box the carrier's field covers, if it is bounded (a mesh).
    virtual std::optional<Box> bounds() const { return std::nullopt; }

    /// The frame of an axisymmetric field (a wedge mesh).
    virtual std::optional<AxisymmetricFrame> axisymmetry() const { return std::nullopt; }

    /// The normal of the plane of a 2-D field (a mesh one cell thick between `empty` patches).
    virtual std::optional<Vec3> planeNormal() const { return std::nullopt; }

    /// Short human-readable description for the run summary, e.g. "analyticJet (axisymmetric)".
    virtual std::string describe() const = 0;
};

} // namespace slides
