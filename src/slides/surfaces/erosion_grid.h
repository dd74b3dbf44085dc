// ErosionGrid: the accumulated damage of a porous layer under particle impacts (Section 5.2).
//
// The layer (surfaces/erosion_settings.h) is a square of side w and depth d under its plane, a
// grid of (cells + 1) points in each direction. Its moduli are the porous estimate of Eq. 5.3
// (physics/porous_moduli.h) from the matrix material. Each impact presses a Hertz contact into
// it: from the normal approach speed v_n, the largest overlap δ = (15 m* v_n²/(16 E* √R*))^(2/5)
// gives the peak normal load P = 4/3 E* √R* δ^(3/2) over the contact radius a = √(R* δ) (Johnson
// §11.4), and the impulse law's tangential-to-normal impulse ratio the tangential load Q =
// P·|J_t|/J_n at that instant. Their stresses (physics/half_space_stress.h, with the layer's
// Poisson ratio) are stresses of the porous continuum; the matrix between the pores carries them as
// the effective stress σ/(1 − D) of Lemaitre's strain equivalence, with the porosity an initial
// damage D = 1 − E_layer/E_matrix. A point where that stress's σ_eq (Eq. 5.5) exceeds σ₀
// (Σ > 0, Eq. 5.6) counts the impact (the accumulated damage); it keeps its peak σ_eq.
// Each impact also records σ_eq on the layer's centre line, at every grid depth (the points of
// the reference's Fig. 5.6, near the stream's centreline across the thickness).
// Costs nothing unless a surface erodes (SurfaceImpacts keeps a grid only for those).
#pragma once

#include "slides/core/vector.h"
#include "slides/physics/contact_pair.h"
#include "slides/physics/half_space_stress.h"
#include "slides/surfaces/erosion_settings.h"

#include <cstdint>
#include <vector>

namespace slides {

class ErosionGrid {
public:
    /// The layer under the plane (point, unit normal into the gas) of a matrix material.
    ErosionGrid(const Vec3& point, const Vec3& normal, const MaterialSettings& matrix,
                const ErosionSettings& settings);

    /// The contact loads of a sphere (radius, mass, material) meeting the layer at normal
    /// speed normalSpeed, with the impulse law's tangential-to-normal impulse ratio.
    HertzLoad impactLoad(double radius, double mass, const MaterialSettings& particle,
                         double normalSpeed, double tangentialRatio) const;

    /// Applies an impact at time [s] centred at contact (a point of the plane) with its load,
    /// the tangential part along the unit tangent (in the plane).
    void applyImpact(double time, const Vec3& contact, const Vec3& tangent, const HertzLoad& load);

    /// One impact's σ_eq on the centre line: time [s] and one value a grid depth [Pa].
    struct CentreLineStress {
        double time;
        std::vector<double> equivalentStress;
    };

    std::array<int, 3> points() const { return {cells_[0] + 1, cells_[1] + 1, cells_[2] + 1}; }
    /// Grid point (i, j, k): i, j across the width, k the depth from the surface (k = 0).
    Vec3 position(int i, int j, int k) const;
    std::size_t index(int i, int j, int k) const {
        const auto p = points();
        return static_cast<std::size_t>(i) +
               static_cast<std::size_t>(p[0]) *
                   (static_cast<std::size_t>(j) + static_cast<std::size_t>(p[1]) * k);
    }
    /// Impacts that raised σ_eq above σ₀ at each point (x fastest, then y, then depth).
    const std::vector<std::uint32_t>& damage() const { return damage_; }
    /// The largest σ_eq at each point so far [Pa].
    const std::vector<double>& peakEquivalentStress() const { return peak_; }
    /// Volume of the points damaged at least once (each point's cell share) [m³].
    double damagedVolume() const;
    std::uint64_t impacts() const { return impacts_; }
    /// σ_eq on the centre line, impact by impact.
    const std::vector<CentreLineStress>& centreLineHistory() const { return history_; }

    /// The layer's frame: two in-plane axes and the depth direction (−normal).
    const Vec3& origin() const { return origin_; }
    const Mat3& axes() const { return axes_; }
    const Vec3& spacing() const { return spacing_; }
    const ElasticMaterial& layer() const { return layer_; }
    /// 1/(1 − D): the matrix's stress per the layer's (strain equivalence).
    double stressConcentration() const { return concentration_; }

private:
    Vec3 origin_;  ///< the corner point (0, 0, 0) of the grid, on the surface
    Mat3 axes_;    ///< columns: in-plane e₁, e₂, depth e₃
    Vec3 spacing_; ///< [m]
    std::array<int, 3> cells_;
    double threshold_;
    MaterialSettings layerModuli_;
    ElasticMaterial layer_;
    double concentration_;
    std::vector<std::uint32_t> damage_;
    std::vector<double> peak_;
    std::uint64_t impacts_ = 0;
    std::vector<CentreLineStress> history_;
};

} // namespace slides
