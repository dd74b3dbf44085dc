// ctest-labels: robustness carrier
// The nozzle disc must lie inside the mesh: a disc partly outside would inject its particles
// outside, where they escape at once. On the boxAscii mesh (about 0.12 × 0.11 × 0.12 m) a disc
// of radius 0.08 m about (0.05 0.05 0.06) reaches past the walls and is refused; one of radius
// 0.01 m about the same centre lies inside and runs.
#include "../support/case_runs.h"

#include <gtest/gtest.h>

#include <fstream>

namespace slides {
namespace {

namespace fs = std::filesystem;

/// The boxAscii mesh with a uniform U and the impinging jet's dictionary, its nozzle moved into
/// the box with the given radius.
void writeBoxCase(const fs::path& directory, const std::string& radius) {
    fs::copy(fs::path(SLIDES_SOURCE_DIR) / "tests/foam/data/boxAscii/constant",
             directory / "constant", fs::copy_options::recursive);
    fs::create_directories(directory / "0");
    std::ofstream(directory / "0" / "U")
        << "FoamFile\n{\n    format ascii;\n    class volVectorField;\n    object U;\n}\n"
           "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\nboundaryField\n{\n"
           "    inlet { type fixedValue; value uniform (1 0 0); }\n"
           "    outlet { type zeroGradient; }\n    walls { type noSlip; }\n"
           "    sides { type symmetry; }\n}\n";
    std::string dictionary = test::slurp(fs::path(SLIDES_SOURCE_DIR) /
                                         "foamCases/impingingJet/constant/slidesProperties");
    const auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = dictionary.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        dictionary.replace(at, from.size(), to);
    };
    replace("centre      (0 0 0);", "centre      (0.05 0.05 0.06);");
    replace("radius      2e-3;", "radius      " + radius + ";");
    std::ofstream(directory / "constant" / "slidesProperties") << dictionary;
}

TEST(NozzleDisc, PartlyOutsideTheMeshIsRefused) {
    test::ScratchDirectory scratch("nozzleDiscOutside");
    writeBoxCase(scratch.path, "0.08");
    const fs::path log = scratch.path / "log";
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet", log), 2);
    // 235 of the 512 points (46 %) lie outside: the disc reaches past every side of the skewed
    // box (an upright 0.11 × 0.12 m rectangle would leave 35 % of it outside).
    const std::string message = test::slurp(log);
    const std::string where =
        (scratch.path / "constant" / "slidesProperties").string() + ":28: key 'nozzle.radius': ";
    EXPECT_NE(message.find(where + "the nozzle disc of radius 0.08 m is not inside the OpenFOAM "
                                   "mesh: 46 % of it (235 of 512 points spread evenly over it) "
                                   "lies outside"),
              std::string::npos)
        << message;
    EXPECT_FALSE(fs::exists(scratch.path / "slides")) << "bad input must not create output";
}

TEST(NozzleDisc, InsideTheMeshIsAccepted) {
    test::ScratchDirectory scratch("nozzleDiscInside");
    writeBoxCase(scratch.path, "0.01");
    const fs::path log = scratch.path / "log";
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet --end-time 1e-4", log), 0)
        << test::slurp(log);
}

} // namespace
} // namespace slides
