// ctest-labels: robustness carrier
// A particle that leaves the mesh through a boundary face is counted under that face's patch in
// summary.json's escapedThrough, never under `domain` (which is for the domain box alone):
// the boxAscii mesh (tests/foam/data) in a uniform stream U = (1 0 0) m/s, 1000 of the impinging
// jet's spray particles injected inside it and its target moved 10 m away, so the particles
// leave through the outlet (and a few through the walls and sides); a step of 0.1 ms moves them
// 0.1 mm, a three-hundredth of a cell. With the lattice scheme the particles' walks
// start nowhere (the lattice serves them without a tetrahedron): the search for a point outside
// the mesh walks from the nearest cell to the face it lies beyond. Before, 62 of 7864 escapes
// (8000 particles; 13 of 993 with the 1000 here) were counted as `domain`.
#include "../support/case_runs.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

namespace slides {
namespace {

namespace fs = std::filesystem;

class EscapePatches : public ::testing::TestWithParam<const char*> {};

TEST_P(EscapePatches, EveryEscapeIsCountedUnderThePatchItLeftThrough) {
    test::ScratchDirectory scratch(std::string("escapePatches-") + GetParam());
    fs::copy(fs::path(SLIDES_SOURCE_DIR) / "tests/foam/data/boxAscii/constant",
             scratch.path / "constant", fs::copy_options::recursive);
    fs::create_directories(scratch.path / "0");
    std::ofstream(scratch.path / "0" / "U")
        << "FoamFile\n{\n    format ascii;\n    class volVectorField;\n    object U;\n}\n"
           "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\nboundaryField\n{\n"
           "    inlet { type fixedValue; value uniform (1 0 0); }\n"
           "    outlet { type zeroGradient; }\n    walls { type noSlip; }\n"
           "    sides { type symmetry; }\n}\n";
    std::string dictionary = test::slurp(fs::path(SLIDES_SOURCE_DIR) /
                                         "foamCases/impingingJet/constant/slidesProperties");
    dictionary = std::regex_replace(dictionary, std::regex("centre      \\(0 0 0\\);"),
                                    "centre      (0.05 0.05 0.06);");
    dictionary =
        std::regex_replace(dictionary, std::regex("radius      2e-3;"), "radius      0.01;");
    dictionary =
        std::regex_replace(dictionary, std::regex("standoff        0.06;"), "standoff        10;");
    dictionary = std::regex_replace(dictionary, std::regex("count       8000;"), "count 1000;");
    dictionary = std::regex_replace(dictionary, std::regex("dt              1e-5;"), "dt 1e-4;");
    dictionary = std::regex_replace(dictionary, std::regex("interpolation   cellPoint;"),
                                    std::string("interpolation   ") + GetParam() + ";");
    std::ofstream(scratch.path / "constant" / "slidesProperties") << dictionary;
    ASSERT_EQ(test::runCli(scratch.path.string() + " --quiet --threads 2", scratch.path / "log"), 0)
        << test::slurp(scratch.path / "log");
    const auto summary =
        nlohmann::json::parse(test::slurp(scratch.path / "slides" / "summary.json"));
    const auto& particles = summary["particles"];
    long escaped = 0;
    for (const auto& [exit, count] : particles["escapedThrough"].items()) {
        EXPECT_NE(exit, "domain") << count << " escapes not named by their patch";
        escaped += count.get<long>();
    }
    EXPECT_EQ(escaped, particles["escaped"].get<long>());
    EXPECT_GT(particles["escapedThrough"]["outlet"].get<long>(), 0.9 * escaped);
}

INSTANTIATE_TEST_SUITE_P(Schemes, EscapePatches, ::testing::Values("cellPoint", "lattice"));

} // namespace
} // namespace slides
