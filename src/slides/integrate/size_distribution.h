// Size distribution: draws particle radii from particles.radiusDistribution (or an injector's),
// number- or mass-weighted, truncated to [minimum, maximum].
//
//     radiusDistribution { type rosinRammler; scale 20e-6; spread 2.5; minimum 2e-6;
//                          maximum 60e-6; weighting mass; }
//     radiusDistribution { type table; file "constant/sizes.csv"; weighting mass; }
//
// fixed, normal and logNormal are drawn from a normal deviate and redrawn outside [minimum,
// maximum] (a mass-weighted logNormal is the number logNormal of median r_m e^(−3σ²),
// Hatch–Choate). rosinRammler, F(r) = 1 − exp(−(r/r̄)^n), is drawn by inverting its truncated
// cumulative distribution: in closed form when number-weighted; when mass-weighted, the number
// distribution f_n ∝ f_m/r³ is integrated once (Simpson) onto a table of 4096 intervals in ln r
// and inverted on it (its error in F below 1e-6, far below the 0.005 a test of 1e5 draws
// resolves). table is a measured cumulative distribution, linear in r between its points: the
// number uniform in r within an interval, or with mass weighting the mass, so that the number
// density there is ∝ r⁻³, drawn exactly by r = (a⁻² − u(a⁻² − b⁻²))^(−1/2).
// Each draw uses the stream (seed, particle id, radius): independent of thread count and order.
#pragma once

#include "slides/integrate/injection_settings.h"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace slides {

class RadiusSampler {
public:
    explicit RadiusSampler(const RadiusDistribution& distribution);
    /// The radius of particle id [m].
    double draw(std::uint64_t seed, std::uint64_t id) const;
    /// Mean radius of the (truncated) number distribution [m].
    double meanRadius() const;

private:
    /// How the number is spread within an interval of the table.
    enum class Within { uniformInLogRadius, uniformInRadius, inverseCube };
    void tabulateRosinRammler();
    void tabulateMeasured();
    /// The radius at number-cumulative fraction u of the table.
    double fromTable(double u) const;

    RadiusDistribution distribution_;
    Within within_ = Within::uniformInRadius;
    std::vector<double> radius_;     ///< table nodes [m]
    std::vector<double> cumulative_; ///< number fraction below each node, 0 … 1
};

/// A radius drawn from the distribution for particle id (truncated by redrawing).
double drawRadius(const RadiusDistribution& distribution, std::uint64_t seed, std::uint64_t id);

/// Rosin–Rammler's cumulative mass or number fraction below r, untruncated.
double rosinRammlerCumulative(double radius, double scale, double spread);

/// Reads a table file (columns r or d [m], and F, the cumulative fraction below) into
/// distribution.tableRadius and tableCumulative; a bad file throws InputError at file:line.
void readSizeTable(const std::filesystem::path& file, RadiusDistribution& distribution);

} // namespace slides
