// ctest-labels: robustness carrier
// Foreign or damaged OpenFOAM cases the reader refuses with one message naming the file (and
// line and key where there is one): a field of the wrong dimensions, a U without an entry for a
// patch of the mesh, an inverted cell, U beside U.gz, and a field that inflates beyond what the
// mesh says it can hold. Through slides-track each ends in exit status 2.
#include "../support/case_runs.h"
#include "slides/carrier/foam_field.h"
#include "slides/carrier/foam_mesh.h"
#include "slides/core/error.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <fstream>
#include <functional>

#include <unistd.h>

namespace slides {
namespace {

namespace fs = std::filesystem;

const fs::path data = fs::path(SLIDES_SOURCE_DIR) / "tests/foam/data";

const std::string velocityHeader =
    "FoamFile\n{\n    format ascii;\n    class volVectorField;\n    object U;\n}\n";
const std::string completeBoundary =
    "boundaryField\n{\n    inlet { type fixedValue; value "
    "uniform (1 0 0); }\n    outlet { type zeroGradient; }\n"
    "    walls { type noSlip; }\n    sides { type symmetry; }\n}\n";

/// The boxAscii mesh (inlet, outlet, walls, sides; 12 cells) in a scratch case.
class ForeignCase : public ::testing::Test {
protected:
    void SetUp() override {
        case_ = fs::temp_directory_path() / ("slides_foreign_case_" + std::to_string(::getpid()));
        fs::remove_all(case_);
        fs::create_directories(case_ / "0");
        fs::copy(data / "boxAscii" / "constant", case_ / "constant", fs::copy_options::recursive);
    }
    void TearDown() override { fs::remove_all(case_); }

    void writeVelocity(const std::string& body) {
        std::ofstream(case_ / "0" / "U") << velocityHeader << body;
    }
    void writePoints(const std::vector<Vec3>& points) {
        std::ofstream out(case_ / "constant" / "polyMesh" / "points");
        out << "FoamFile\n{\n    format ascii;\n    class vectorField;\n    object points;\n}\n"
            << points.size() << "\n(\n";
        out.precision(17);
        for (const Vec3& point : points)
            out << "(" << point.x() << " " << point.y() << " " << point.z() << ")\n";
        out << ")\n";
    }
    /// The error reading the mesh and then U.
    InputError readError() {
        try {
            const FoamMesh mesh = readFoamMesh(case_);
            readFoamVolField<Vec3>(case_ / "0", "U", mesh);
        } catch (const InputError& error) {
            return error;
        }
        ADD_FAILURE() << "no error";
        return InputError("", 0, "", "");
    }

    fs::path case_;
};

TEST_F(ForeignCase, VelocityWithTheDimensionsOfAPressure) {
    writeVelocity("dimensions [0 2 -2 0 0 0 0];\ninternalField uniform (1 0 0);\n" +
                  completeBoundary);
    EXPECT_EQ(std::string(readError().what()),
              (case_ / "0" / "U").string() +
                  ":7: key 'dimensions': [0 2 -2 0 0 0 0] are not the dimensions of U, a "
                  "velocity [0 1 -1 0 0 0 0]");
}

TEST_F(ForeignCase, FiveExponentDimensionsOfAVelocityAreRead) {
    writeVelocity("dimensions [0 1 -1 0 0];\ninternalField uniform (1 0 0);\n" + completeBoundary);
    const FoamMesh mesh = readFoamMesh(case_);
    EXPECT_EQ(readFoamVolField<Vec3>(case_ / "0", "U", mesh).cells.at(11), Vec3(1, 0, 0));
}

TEST_F(ForeignCase, VelocityWithoutDimensions) {
    writeVelocity("internalField uniform (1 0 0);\n" + completeBoundary);
    EXPECT_EQ(std::string(readError().what()),
              (case_ / "0" / "U").string() +
                  ": key 'dimensions': missing; U is a velocity [0 1 -1 0 0 0 0]");
}

TEST_F(ForeignCase, VelocityMissingABoundaryPatch) {
    writeVelocity("dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\n"
                  "boundaryField\n{\n    inlet { type fixedValue; value uniform (1 0 0); }\n"
                  "    walls { type noSlip; }\n    sides { type symmetry; }\n}\n");
    EXPECT_EQ(std::string(readError().what()),
              (case_ / "0" / "U").string() +
                  ":9: key 'boundaryField': no entry for patch 'outlet' of the mesh");
}

TEST_F(ForeignCase, ConstraintTypesCoverTheSymmetryPatch) {
    writeVelocity("dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\n"
                  "boundaryField\n{\n    #includeEtc \"caseDicts/setConstraintTypes\"\n"
                  "    \"(inlet|outlet|walls)\" { type fixedValue; value uniform (1 0 0); }\n}\n");
    const FoamMesh mesh = readFoamMesh(case_);
    EXPECT_EQ(readFoamVolField<Vec3>(case_ / "0", "U", mesh).patchValues[0].size(), 4u);
}

// The box mirrored in x: every cell is inside out (OpenFOAM's checkMesh: "Zero or negative
// cell volume detected"). Its first cell's volume is minus that of the box's first cell.
TEST_F(ForeignCase, MirroredMeshHasInvertedCells) {
    const FoamMesh box = readFoamMesh(data / "boxAscii");
    std::vector<Vec3> mirrored = box.points;
    for (Vec3& point : mirrored) point.x() = -point.x();
    writePoints(mirrored);
    const InputError error = readError();
    EXPECT_EQ(error.file(), (case_ / "constant" / "polyMesh").string());
    EXPECT_TRUE(error.reason().starts_with("cell 0 is inverted or tangled: volume -"))
        << error.what();
    std::ostringstream volume;
    volume << -box.cellVolumes[0];
    EXPECT_NE(error.reason().find("volume " + volume.str() + " m³"), std::string::npos)
        << error.what();
}

// One interior point moved in x through its neighbours to 1 cm beyond the box's side: the cells
// that share it fold over (tetrahedra of the locator's decomposition turn inside out).
TEST_F(ForeignCase, TangledCellIsRefused) {
    FoamMesh box = readFoamMesh(data / "boxAscii");
    const auto interior = std::find_if(box.points.begin(), box.points.end(), [&](const Vec3& p) {
        return (p.array() > box.boundsMin.array() + 1e-9).all() &&
               (p.array() < box.boundsMax.array() - 1e-9).all();
    });
    ASSERT_NE(interior, box.points.end());
    (*interior).x() += 0.9 * (box.boundsMax.x() - interior->x()) + 0.01;
    writePoints(box.points);
    const InputError error = readError();
    EXPECT_EQ(error.file(), (case_ / "constant" / "polyMesh").string());
    EXPECT_NE(error.reason().find("is inverted or tangled"), std::string::npos) << error.what();
}

TEST_F(ForeignCase, BothPlainAndCompressedVelocity) {
    writeVelocity("dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\n" +
                  completeBoundary);
    fs::copy_file(case_ / "0" / "U", case_ / "0" / "U.gz");
    EXPECT_EQ(std::string(readError().what()),
              (case_ / "0" / "U").string() +
                  ": both U and U.gz exist: remove the one that is not the result");
}

// 16 MB of blanks compress to 16 kB; the field of a 12-cell mesh with 32 boundary faces cannot
// hold more than 1 MiB + 128 bytes per cell and 4 × 128 per boundary face.
TEST_F(ForeignCase, CompressedFieldInflatingBeyondWhatTheMeshHolds) {
    const fs::path file = case_ / "0" / "U.gz";
    gzFile out = gzopen(file.c_str(), "wb");
    ASSERT_NE(out, nullptr);
    gzputs(out, velocityHeader.c_str());
    const std::string blanks(1 << 20, ' ');
    for (int megabyte = 0; megabyte < 16; ++megabyte)
        ASSERT_EQ(gzwrite(out, blanks.data(), static_cast<unsigned>(blanks.size())),
                  static_cast<int>(blanks.size()));
    gzclose(out);
    EXPECT_LT(fs::file_size(file), 100'000u);
    EXPECT_EQ(std::string(readError().what()),
              file.string() + ": inflates to more than 1066496 bytes, more than a field of 12 "
                              "cells and 32 boundary faces can hold");
}

// The same refusal through the command line: one line on stderr, exit status 2.
TEST_F(ForeignCase, CommandLineExitsWithStatusTwo) {
    writeVelocity("dimensions [0 1 0 0 0 0 0];\ninternalField uniform (1 0 0);\n" +
                  completeBoundary);
    fs::copy_file(fs::path(SLIDES_SOURCE_DIR) / "foamCases/impingingJet/constant/slidesProperties",
                  case_ / "constant" / "slidesProperties");
    const fs::path log = case_ / "log";
    EXPECT_EQ(test::runCli(case_.string(), log), 2);
    EXPECT_EQ(test::slurp(log), "\nslides-track: error: " + (case_ / "0" / "U").string() +
                                    ":7: key 'dimensions': [0 1 0 0 0 0 0] are not the "
                                    "dimensions of U, a velocity [0 1 -1 0 0 0 0]\n");
}

} // namespace
} // namespace slides
