// ctest-labels: packing
// Packed ensembles (Section 4.3; integrate/ensemble.h, packing_random_addition.h,
// packing_growth.h), checked by brute force over every pair, not through the cell grid:
// - no overlaps and every sphere inside the walls, for both methods, equal and unequal spheres;
// - random sequential addition (Widom 1966, Fig. 4.1) of equal spheres saturates at
//   φ_s = 0.38413 (Zhang & Torquato 2013, Phys. Rev. E 88, 053312) and stalls there: no point of
//   the box is left where another sphere fits;
// - Lubachevsky–Stillinger growth (Eq. 4.30–4.32, Algorithm 3) packs equal spheres to
//   φ = 0.625, and jams between 0.62 and 0.66 when asked for more (random close packing
//   φ ≈ 0.64, Scott & Kilgour 1969; maximally random jammed 0.637, Torquato, Truskett &
//   Debenedetti 2000);
// - the radial distribution function of a dense packing peaks at contact, has the hole of the
//   first shell below 1 and tends to 1 (Bernal & Finney's random packings; Donev, Torquato &
//   Stillinger 2005, Phys. Rev. E 71, 011105, Fig. 1);
// - an injector of model ensemble starts its particles at rest at the packing's points, and a
//   count beyond saturation is refused naming the key.
#include "../support/case_runs.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"
#include "slides/core/random.h"
#include "slides/integrate/ensemble.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <vector>

using namespace slides;

namespace {

/// A cube of edge `edge` sphere diameters (radius 1/2), periodic or walled.
PackingRegion cube(double edge, bool periodic) {
    PackingRegion region;
    region.upper = Vec3::Constant(edge);
    region.periodic = periodic;
    return region;
}

/// The largest overlap of two spheres, over every pair (≤ 0: none) [m].
double largestOverlap(const PackingRegion& region, const PackedEnsemble& packed) {
    double worst = -std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < packed.centres.size(); ++i)
        for (std::size_t j = i + 1; j < packed.centres.size(); ++j)
            worst =
                std::max(worst, packed.radii[i] + packed.radii[j] -
                                    region.separation(packed.centres[i], packed.centres[j]).norm());
    return worst;
}

bool allInside(const PackingRegion& region, const PackedEnsemble& packed) {
    for (std::size_t i = 0; i < packed.centres.size(); ++i)
        if (!region.holds(packed.centres[i], packed.radii[i])) return false;
    return true;
}

std::vector<double> equalRadii(std::size_t count) { return std::vector<double>(count, 0.5); }

/// Radii normal about 0.5 with deviation 0.1, cut to [0.3, 0.7] (drawn as an injector would).
std::vector<double> unequalRadii(std::size_t count) {
    std::vector<double> radii(count);
    for (std::size_t k = 0; k < count; ++k) {
        RandomStream random(3, k, RandomPurpose::radius);
        do radii[k] = 0.5 + 0.1 * random.normal();
        while (radii[k] < 0.3 || radii[k] > 0.7);
    }
    return radii;
}

/// g(r) of equal spheres of diameter 1 in a periodic cube, in bins of width dr from 0.
std::vector<double> radialDistribution(const PackingRegion& region, const PackedEnsemble& packed,
                                       double dr, std::size_t bins) {
    std::vector<double> g(bins, 0.0);
    const auto n = static_cast<double>(packed.centres.size());
    for (std::size_t i = 0; i < packed.centres.size(); ++i)
        for (std::size_t j = i + 1; j < packed.centres.size(); ++j) {
            const double r = region.separation(packed.centres[i], packed.centres[j]).norm();
            if (r < dr * static_cast<double>(bins)) g[static_cast<std::size_t>(r / dr)] += 2;
        }
    const double density = n / region.volume();
    for (std::size_t b = 0; b < bins; ++b) {
        const double inner = dr * static_cast<double>(b), outer = inner + dr;
        const double shell =
            4.0 / 3.0 * std::numbers::pi * (std::pow(outer, 3) - std::pow(inner, 3));
        g[b] /= n * density * shell;
    }
    return g;
}

PackedEnsemble pack(PackingMethod method, const PackingRegion& region,
                    const std::vector<double>& radii, std::uint64_t seed = 1) {
    EnsembleSettings settings;
    settings.method = method;
    settings.region = region;
    return packEnsemble(settings, radii, seed, 0);
}

/// The number of spheres of diameter 1 at volume fraction φ in the region.
std::size_t countAt(double fraction, const PackingRegion& region) {
    return static_cast<std::size_t>(
        std::lround(fraction * region.volume() / (std::numbers::pi / 6)));
}

/// Equal spheres grown in a periodic cube of 6 diameters until they jam (asked for φ = 0.72).
const PackedEnsemble& jammedPacking() {
    static const PackedEnsemble packed = pack(PackingMethod::lubachevskyStillinger, cube(6, true),
                                              equalRadii(countAt(0.72, cube(6, true))));
    return packed;
}

/// Unequal spheres at volume fraction φ packed into the region by the method: every one
/// placed, none overlapping another or crossing the region's walls.
void expectUnequalSpheresPackedInside(PackingMethod method, const PackingRegion& region,
                                      double fraction) {
    const PackedEnsemble packed = pack(method, region, unequalRadii(countAt(fraction, region)));
    ASSERT_TRUE(packed.complete);
    EXPECT_LE(largestOverlap(region, packed), 0.0);
    EXPECT_TRUE(allInside(region, packed));
}

} // namespace

TEST(RandomSequentialAddition, UnequalSpheresInACylinderNeitherOverlapNorCrossItsWall) {
    PackingRegion region;
    region.shape = PackingShape::cylinder;
    region.base = Vec3(1, 2, 3);
    region.axis = Vec3(1, 1, 0).normalized();
    region.radius = 4;
    region.length = 10;
    expectUnequalSpheresPackedInside(PackingMethod::randomSequentialAddition, region, 0.2);
}

TEST(RandomSequentialAddition, EqualSpheresSaturateAtTheKnownFractionAndStall) {
    // A periodic cube of 10 diameters holds about 734 spheres at saturation; the fraction of
    // one such box scatters by 0.0025 (measured over seeds 1–8: 0.3822–0.3890, mean 0.3847),
    // so the mean of 4 packings by 0.0013: 0.004 is 3 deviations.
    const PackingRegion region = cube(10, true);
    double sum = 0;
    PackedEnsemble packed;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
        packed = pack(PackingMethod::randomSequentialAddition, region, equalRadii(1000), seed);
        EXPECT_FALSE(packed.complete);
        ASSERT_TRUE(packed.saturated);
        sum += packed.volumeFraction(region.volume());
    }
    EXPECT_NEAR(sum / 4, 0.38413, 0.004);
    EXPECT_LE(largestOverlap(region, packed), 0.0);
    // Stalled: no point of the box is clear of every exclusion sphere (radius one diameter).
    RandomStream random(99, 0, RandomPurpose::injection);
    int fits = 0;
    for (int attempt = 0; attempt < 20000; ++attempt) {
        const Vec3 point(10 * random.uniform(), 10 * random.uniform(), 10 * random.uniform());
        bool clear = true;
        for (const Vec3& centre : packed.centres)
            clear = clear && region.separation(point, centre).squaredNorm() >= 1.0;
        fits += clear;
    }
    EXPECT_EQ(fits, 0);
}

TEST(LubachevskyStillinger, PacksEqualSpheresDenselyWithoutOverlap) {
    const PackingRegion region = cube(6, true);
    const PackedEnsemble packed =
        pack(PackingMethod::lubachevskyStillinger, region, equalRadii(countAt(0.625, region)));
    ASSERT_TRUE(packed.complete);
    EXPECT_GE(packed.volumeFraction(region.volume()), 0.62);
    EXPECT_LE(largestOverlap(region, packed), 0.0);
}

TEST(LubachevskyStillinger, JamsNearRandomClosePacking) {
    const PackingRegion region = cube(6, true);
    const PackedEnsemble& packed = jammedPacking();
    EXPECT_FALSE(packed.complete);
    const double jammed = packed.volumeFraction(region.volume());
    EXPECT_GT(jammed, 0.62);
    EXPECT_LT(jammed, 0.66);
    EXPECT_LE(largestOverlap(region, packed), 0.0);
}

TEST(LubachevskyStillinger, UnequalSpheresInsideWallsNeitherOverlapNorCrossThem) {
    expectUnequalSpheresPackedInside(PackingMethod::lubachevskyStillinger, cube(6, false), 0.45);
}

TEST(LubachevskyStillinger, RadialDistributionPeaksAtContact) {
    // Bins of 0.05 diameters over 3 diameters; measured: 9.9 at contact, 0.49–0.70 across
    // the first shell's hole, 1.3 and 1.7 at the split second peak √3 d and 2d, 0.8 after it.
    const PackingRegion region = cube(6, true);
    const PackedEnsemble& packed = jammedPacking();
    const double diameter = 2 * packed.radii[0];
    const double dr = 0.05 * diameter;
    const std::vector<double> g = radialDistribution(region, packed, dr, 60);
    const auto at = [&](double r) { return g[static_cast<std::size_t>(r / 0.05)]; }; // r in d
    const auto mean = [&](double from, double to) {
        double sum = 0;
        for (double r = from; r < to - 1e-9; r += 0.05) sum += at(r);
        return sum / std::round((to - from) / 0.05);
    };
    EXPECT_EQ(std::max_element(g.begin(), g.end()) - g.begin(), 20); // [d, 1.05 d)
    EXPECT_GT(at(1.0), 5.0);
    EXPECT_EQ(mean(0, 0.95), 0.0);
    EXPECT_LT(mean(1.2, 1.5), 0.8);
    EXPECT_GT(at(1.725), 1.1); // √3 d
    EXPECT_GT(at(1.975), 1.3); // 2 d
    EXPECT_LT(at(2.1), 1.0);
    EXPECT_NEAR(mean(2.5, 3.0), 1.0, 0.15);
}

namespace {

/// The default case with its nozzle injection replaced by an injector of model ensemble.
std::string ensembleCase(long count, const std::string& method) {
    std::string text = test::slurp(test::defaultCase / "constant" / "slidesProperties");
    const auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = text.find(from);
        if (at == std::string::npos) throw std::logic_error("not in the default case: " + from);
        text.replace(at, from.size(), to);
    };
    replace("count       8000;", "");
    const auto start = text.find("injection\n{");
    text.replace(start, text.find("}\n", start) + 2 - start,
                 "injection { seed 1; }\ninjectors { bed { model ensemble; count " +
                     std::to_string(count) + "; ensembleCoeffs { method " + method +
                     "; shape box; min (0.01 -8e-4 -8e-4); max (0.0116 8e-4 8e-4); } } }\n");
    return text;
}

Scene sceneOf(const test::ScratchDirectory& scratch, const std::string& text) {
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
    return readScene(scratch.path);
}

} // namespace

TEST(EnsembleInjector, ItsRowsAreThePackingAtRest) {
    // 600 spheres of 80 µm in a 1.6 mm cube: φ = 0.31 (1000 would fill 0.52).
    test::ScratchDirectory scratch("ensemble-rows");
    const Scene scene = sceneOf(scratch, ensembleCase(600, "lubachevskyStillinger"));
    ASSERT_EQ(scene.injectors.size(), 1u);
    const InjectorSettings& bed = scene.injectors[0];
    ASSERT_EQ(bed.rows.size(), 600u);
    PackedEnsemble packed;
    for (const ParticleRow& row : bed.rows) {
        EXPECT_EQ(row.velocity, Vec3::Zero());
        EXPECT_EQ(row.radius, 80e-6);
        packed.centres.push_back(row.position);
        packed.radii.push_back(row.radius);
    }
    EXPECT_LE(largestOverlap(bed.ensemble.region, packed), 0.0);
    EXPECT_TRUE(allInside(bed.ensemble.region, packed));
}

TEST(EnsembleInjector, ACountBeyondSaturationIsRefusedAtItsKey) {
    // φ = 0.52: beyond random addition's saturation.
    test::ScratchDirectory scratch("ensemble-full");
    try {
        sceneOf(scratch, ensembleCase(1000, "randomSequentialAddition"));
        FAIL() << "no error";
    } catch (const InputError& error) {
        EXPECT_EQ(error.key(), "injectors.bed.count");
        EXPECT_NE(error.reason().find("do not fit"), std::string::npos) << error.reason();
    }
}
