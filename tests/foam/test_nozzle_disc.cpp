// ctest-labels: robustness carrier
// foam-cases: planarJet
// The nozzle disc must lie inside the mesh: a disc partly outside would inject its particles
// outside, where they escape at once. On the boxAscii mesh (about 0.12 × 0.11 × 0.12 m) a disc
// of radius 0.08 m about (0.05 0.05 0.06) reaches past the walls and is refused; one of radius
// 0.01 m about the same centre lies inside and runs. On the 2-D planarJet mesh (0.2 × 0.05 m,
// 1 mm thick) the disc is the slot's line in the plane: 8 mm about y = 0.02 m fits, 30 mm
// reaches below y = 0.
#include "../support/case_runs.h"

#include <gtest/gtest.h>

#include <fstream>

namespace slides {
namespace {

namespace fs = std::filesystem;

/// The impinging jet's dictionary with its nozzle at centre with radius, its target at x = 0.06.
void writeDictionary(const fs::path& directory, const std::string& centre,
                     const std::string& radius) {
    std::string dictionary = test::slurp(fs::path(SLIDES_SOURCE_DIR) /
                                         "foamCases/impingingJet/constant/slidesProperties");
    const auto replace = [&](const std::string& from, const std::string& to) {
        const auto at = dictionary.find(from);
        ASSERT_NE(at, std::string::npos) << from;
        dictionary.replace(at, from.size(), to);
    };
    replace("centre      (0 0 0);", "centre      " + centre + ";");
    replace("radius      2e-3;", "radius      " + radius + ";");
    std::ofstream(directory / "constant" / "slidesProperties") << dictionary;
}

/// The boxAscii mesh with a uniform U, its nozzle moved into the box with the given radius.
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
    writeDictionary(directory, "(0.05 0.05 0.06)", radius);
}

/// The message of the run of scratch's case, which must be refused (exit status 2).
std::string refusalOf(const test::ScratchDirectory& scratch) {
    const fs::path log = scratch.path / "log";
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet", log), 2);
    return test::slurp(log);
}

/// Scratch's case runs for 1e-4 s without error (exit status 0).
void expectAccepted(const test::ScratchDirectory& scratch) {
    const fs::path log = scratch.path / "log";
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet --end-time 1e-4", log), 0)
        << test::slurp(log);
}

TEST(NozzleDisc, PartlyOutsideTheMeshIsRefused) {
    test::ScratchDirectory scratch("nozzleDiscOutside");
    writeBoxCase(scratch.path, "0.08");
    const std::string message = refusalOf(scratch);
    // 235 of the 512 points (46 %) lie outside: the disc reaches past every side of the skewed
    // box (an upright 0.11 × 0.12 m rectangle would leave 35 % of it outside).
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
    expectAccepted(scratch);
}

/// The solved planarJet case with its nozzle on the slot's plane at y = 0.02 m, z = 0.5 mm.
void writePlanarCase(const fs::path& directory, const std::string& radius) {
    test::copySolvedRun("planarJet", directory);
    writeDictionary(directory, "(0.01 0.02 0.0005)", radius);
}

TEST(NozzleDisc, OnATwoDimensionalMeshItIsTheSlotInThePlane) {
    test::ScratchDirectory scratch("nozzleSlotInside");
    writePlanarCase(scratch.path, "8e-3");
    expectAccepted(scratch);
}

TEST(NozzleDisc, SlotPartlyOutsideATwoDimensionalMeshIsRefused) {
    test::ScratchDirectory scratch("nozzleSlotOutside");
    writePlanarCase(scratch.path, "0.03");
    const std::string message = refusalOf(scratch);
    // The slot from y = -0.01 to 0.05 m: its sixth below y = 0, 21 of the 129 points, is outside.
    EXPECT_NE(message.find(":28: key 'nozzle.radius': the nozzle disc of radius 0.03 m is not "
                           "inside the OpenFOAM mesh: 16 % of it (21 of 129 points spread evenly "
                           "over it) lies outside"),
              std::string::npos)
        << message;
}

} // namespace
} // namespace slides
