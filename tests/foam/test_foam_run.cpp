// ctest-labels: foam run
// `slides-track CASE` on an OpenFOAM case: the 5° wedge mesh OpenFOAM wrote
// (tests/foam/data/wedge) with a uniform stream U = (4 0 0) m/s, tracked in 3-D.
#include "../support/case_runs.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <regex>

#include <unistd.h>

namespace {

const std::filesystem::path data = std::filesystem::path(SLIDES_SOURCE_DIR) / "tests/foam/data";

using slides::test::runCli;
using slides::test::slurp;

class FoamRun : public ::testing::Test {
protected:
    void SetUp() override {
        case_ = std::filesystem::temp_directory_path() /
                ("slides_foam_run_" + std::to_string(::getpid()));
        std::filesystem::remove_all(case_);
        std::filesystem::create_directories(case_ / "0");
        std::filesystem::copy(data / "wedge" / "constant", case_ / "constant",
                              std::filesystem::copy_options::recursive);
        std::ofstream(case_ / "0" / "U")
            << "FoamFile { version 2.0; format ascii; class volVectorField; object U; }\n"
               "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (4 0 0);\n"
               "boundaryField\n{\n    inlet { type fixedValue; value uniform (4 0 0); }\n"
               "    outlet { type zeroGradient; }\n    outer { type slip; value uniform (4 0 0); "
               "}\n"
               "    \"(front|back)\" { type wedge; }\n    axis { type empty; }\n}\n";
    }
    void TearDown() override { std::filesystem::remove_all(case_); }

    void writeScene(const std::string& surfaces) {
        std::ofstream(case_ / "constant" / "slidesProperties")
            << "FoamFile { version 2.0; format ascii; class dictionary; object slidesProperties; "
               "}\n"
               "fluid { density 1.1; kinematicViscosity 25e-6; }\n"
               "nozzle { centre (0 0 0); axis (1 0 0); radius 0.01; }\n"
               "carrier { type foamField; foamFieldCoeffs { time latestTime; interpolation "
               "cellPoint; } }\n"
               "particles { count 200; density 1000; radiusDistribution { type fixed; value "
               "5e-6; } }\n"
               "injection { mode allAtStart; seed 3; }\n"
               "time { dt 1e-4; endTime 0.1; }\n"
               "surfaces { "
            << surfaces
            << " }\n"
               "output { interval 0.01; carrierResolution (20 10 10); }\n";
    }

    std::filesystem::path case_;
};

// Particles of response time ρp d²/(18 μ) = 0.2 ms start with the gas velocity in a uniform
// stream, so they keep it exactly: every one reaches the plane at x = 0.08 m, 20 ms later, at
// 4 m/s (to round-off), wherever around the axis it started. No domain is given: the mesh's.
TEST_F(FoamRun, TracksThroughTheWedgeSolutionTo3DTarget) {
    writeScene("target { type plane; point (0.08 0 0); normal (-1 0 0); }");
    ASSERT_EQ(runCli(case_.string() + " --quiet --threads 1", case_ / "log"), 0)
        << slurp(case_ / "log");
    const auto summary = nlohmann::json::parse(slurp(case_ / "slides" / "summary.json"));
    EXPECT_EQ(summary["particles"]["arrived"]["target"].get<long>(), 200);
    EXPECT_NEAR(summary["arrivals"]["target"]["impactSpeed"]["mean"].get<double>(), 4.0, 1e-9);
    EXPECT_NEAR(summary["arrivals"]["target"]["impactSpeed"]["max"].get<double>(), 4.0, 1e-9);
    EXPECT_TRUE(std::filesystem::exists(case_ / "slides" / "carrier.vti"));
    EXPECT_NE(summary["carrier"].get<std::string>().find("axisymmetric wedge"), std::string::npos);
}

// Without a surface they leave the mesh through its outlet: escaped, none left moving, and
// counted by the patch they crossed.
TEST_F(FoamRun, ParticlesLeavingTheMeshEscape) {
    writeScene("");
    ASSERT_EQ(runCli(case_.string() + " --threads 1 --time 0", case_ / "log"), 0)
        << slurp(case_ / "log");
    const auto summary = nlohmann::json::parse(slurp(case_ / "slides" / "summary.json"));
    EXPECT_EQ(summary["particles"]["escaped"].get<long>(), 200);
    EXPECT_EQ(summary["particles"]["escapedThrough"], nlohmann::json({{"outlet", 200}}));
    EXPECT_NE(slurp(case_ / "log").find("escaped through outlet 200"), std::string::npos)
        << slurp(case_ / "log");
    EXPECT_EQ(summary["particles"]["active"].get<long>(), 0);
    EXPECT_LT(summary["time"]["end"].get<double>(), 0.04) << "stopped when all had left";
}

// The lattice scheme on the uniform stream: the lattice reproduces it exactly (error 0 against
// cellPoint, reported in summary.json), and the particles arrive as with cellPoint.
TEST_F(FoamRun, LatticeSchemeReportsItsError) {
    writeScene("target { type plane; point (0.08 0 0); normal (-1 0 0); }");
    const auto text = slurp(case_ / "constant" / "slidesProperties");
    std::ofstream(case_ / "constant" / "slidesProperties")
        << std::regex_replace(text, std::regex("interpolation cellPoint;"),
                              "interpolation lattice; latticeSpacing 0.002;");
    ASSERT_EQ(runCli(case_.string() + " --quiet --threads 1", case_ / "log"), 0)
        << slurp(case_ / "log");
    const auto summary = nlohmann::json::parse(slurp(case_ / "slides" / "summary.json"));
    EXPECT_EQ(summary["particles"]["arrived"]["target"].get<long>(), 200);
    EXPECT_NEAR(summary["arrivals"]["target"]["impactSpeed"]["mean"].get<double>(), 4.0, 1e-9);
    const auto& figures = summary["carrierFigures"];
    EXPECT_EQ(figures["latticeSpacing"].get<double>(), 0.002);
    EXPECT_LT(figures["latticeErrorMax"].get<double>(), 1e-12);
    EXPECT_GT(figures["latticeErrorPoints"].get<double>(), 3000) << "of 4000 random points";
}

// A domain box ending before the outlet (x = 0.05 of 0.1 m): they leave through the box.
TEST_F(FoamRun, EscapesThroughTheDomainBoxAreCountedAsDomain) {
    writeScene("");
    std::ofstream(case_ / "constant" / "slidesProperties", std::ios::app)
        << "domain { min (-1 -1 -1); max (0.05 1 1); }\n";
    ASSERT_EQ(runCli(case_.string() + " --quiet --threads 1 --time 0", case_ / "log"), 0)
        << slurp(case_ / "log");
    const auto summary = nlohmann::json::parse(slurp(case_ / "slides" / "summary.json"));
    EXPECT_EQ(summary["particles"]["escapedThrough"], nlohmann::json({{"domain", 200}}));
}

// Bad input: a time that does not exist, and a missing velocity field, are exit status 2
// with the file named.
TEST_F(FoamRun, MissingTimeOrFieldIsAnInputError) {
    writeScene("");
    EXPECT_EQ(runCli(case_.string() + " --quiet --time 5", case_ / "log"), 2);
    EXPECT_NE(slurp(case_ / "log").find("no time directory 5"), std::string::npos)
        << slurp(case_ / "log");
    std::filesystem::create_directories(case_ / "7");
    std::ofstream(case_ / "7" / "p") << "";
    EXPECT_EQ(runCli(case_.string() + " --quiet --time 7", case_ / "log"), 2);
    EXPECT_NE(slurp(case_ / "log").find("7/U"), std::string::npos) << slurp(case_ / "log");
}

} // namespace
