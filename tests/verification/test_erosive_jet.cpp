// ctest-labels: erosion
// The abrasive jet on a porous layer (foamCases/erosiveJet, the reference's Section 5.2), over a
// small ensemble of streams (two seeds, 60 particles each, a coarse 16 × 16 × 4 grid):
//  - more accumulated damage (the counts summed over the grid; the damaged volume no less) at
//    higher porosity (0.4 against 0.1): the porous layer is softer,
//    so an impact's contact stresses fall (p0 ∝ E*^(4/5)), but the matrix between the pores
//    carries them over its smaller stiffness (σ/(1 − D), D = 1 − E_layer/E), which wins
//    (∝ E*^(−1/5)) — the reference's Fig. 5.6 (bottom);
//  - less accumulated damage at 30° incidence than at normal incidence, at the same speed: the
//    normal speed, which sets the Hertz load, falls by cos 30° (Fig. 5.6);
//  - every impact is counted (the summary's impacts equal the layer's rebounds), and the run's
//    damage.h5 and damage_layer.pvd exist;
//  - checkpoints do not hold the damage grid yet: asking for them is refused, nothing written.
#include "../support/case_runs.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <regex>

namespace slides {
namespace {

using namespace slides::test;

struct Damage {
    double volume = 0;
    double accumulated = 0; ///< the damage counts summed over the grid
    double impacts = 0;
    double rebounds = 0;
};

/// Runs the shipped case with its variables set, in a scratch directory.
Damage runErosiveJet(double porosity, const std::string& axis, int seed) {
    std::string text = slurp(sourceDir / "foamCases/erosiveJet/constant/slidesProperties");
    text = std::regex_replace(text, std::regex("\nporosity +[0-9.]+;"),
                              "\nporosity " + std::to_string(porosity) + ";");
    text = std::regex_replace(text, std::regex("\nstreamAxis +\\([^)]*\\);"),
                              "\nstreamAxis " + axis + ";");
    text = std::regex_replace(text, std::regex("\nparticleCount +[0-9]+;"), "\nparticleCount 60;");
    text = std::regex_replace(text, std::regex("cells +\\([^)]*\\);"), "cells (16 16 4);");
    text =
        std::regex_replace(text, std::regex("\n}\n\ncollisions"),
                           "\n}\n\ninjection { seed " + std::to_string(seed) + "; }\n\ncollisions");
    const ScratchDirectory scratch("erosive-jet-" + std::to_string(seed));
    std::ofstream(scratch.path / "constant/slidesProperties") << text;
    EXPECT_EQ(runCli(scratch.path.string() + " --quiet", scratch.path / "log"), 0)
        << slurp(scratch.path / "log");
    EXPECT_TRUE(std::filesystem::exists(scratch.path / "slides/damage.h5"));
    EXPECT_TRUE(std::filesystem::exists(scratch.path / "slides/damage_layer.pvd"));
    const auto summary = nlohmann::json::parse(slurp(scratch.path / "slides/summary.json"));
    const auto& layer = summary["erosion"]["layer"];
    return {layer["damagedVolume"].get<double>(), layer["accumulatedDamage"].get<double>(),
            layer["impacts"].get<double>(), summary["rebounds"]["layer"].get<double>()};
}

TEST(ErosiveJet, MoreDamageAtHigherPorosityLessAtObliqueIncidence) {
    const std::string normal = "(0 0 -1)", oblique = "(0.5 0 -0.8660254)";
    for (const int seed : {1, 2}) {
        const Damage dense = runErosiveJet(0.1, normal, seed);
        const Damage porous = runErosiveJet(0.4, normal, seed);
        const Damage angled = runErosiveJet(0.1, oblique, seed);
        for (const Damage& run : {dense, porous, angled}) {
            EXPECT_GT(run.impacts, 50);
            EXPECT_EQ(run.impacts, run.rebounds);
        }
        EXPECT_GT(dense.accumulated, 0);
        EXPECT_GT(porous.accumulated, dense.accumulated) << "seed " << seed;
        EXPECT_GE(porous.volume, dense.volume) << "seed " << seed;
        EXPECT_LT(angled.accumulated, dense.accumulated) << "seed " << seed;
        EXPECT_LE(angled.volume, dense.volume) << "seed " << seed;
    }
}

TEST(ErosiveJet, CheckpointsAreRefusedUntilTheyHoldTheDamageGrid) {
    const ScratchDirectory scratch("erosive-jet-checkpoint");
    std::filesystem::copy(sourceDir / "foamCases/erosiveJet/constant/slidesProperties",
                          scratch.path / "constant/slidesProperties");
    EXPECT_EQ(
        runCli(scratch.path.string() + " --quiet --checkpoint-every 10", scratch.path / "log"), 2);
    EXPECT_NE(slurp(scratch.path / "log")
                  .find("key '--checkpoint-every': checkpoints do not hold the damage grid of "
                        "surface layer"),
              std::string::npos)
        << slurp(scratch.path / "log");
    EXPECT_FALSE(std::filesystem::exists(scratch.path / "slides"));
}

} // namespace
} // namespace slides
