// ctest-labels: foam carrier
// The OpenFOAM reader on files OpenFOAM v1912 wrote (tests/foam/data/README.md): polyMesh and
// fields in ASCII, binary and gzip-compressed ASCII, on a hex and a polyhedral mesh; errors.
#include "slides/carrier/foam_carrier.h"
#include "slides/carrier/foam_field.h"
#include "slides/carrier/foam_mesh.h"
#include "slides/core/error.h"

#include <gtest/gtest.h>
#include <zlib.h>

#include <cstdlib>
#include <cstring>
#include <fstream>

#include <unistd.h>

namespace slides {
namespace {

const std::filesystem::path data = std::filesystem::path(SLIDES_SOURCE_DIR) / "tests/foam/data";

class OpenFoamWrittenCase : public ::testing::TestWithParam<const char*> {};

// OpenFOAM's own cell centres (writeCellCentres, 17 digits) and volumes agree with the
// geometry computed from the mesh read here: the same algorithm (primitiveMesh*.C), so the
// tolerance is round-off, 1e-12 of the 0.1 m box.
TEST_P(OpenFoamWrittenCase, MeshGeometryMatchesOpenFoamsCellCentresAndVolumes) {
    const auto caseDirectory = data / GetParam();
    const FoamMesh mesh = readFoamMesh(caseDirectory);
    const auto centres = readFoamVolField<Vec3>(caseDirectory / "0", "C", mesh);
    const auto volumes = readFoamVolField<double>(caseDirectory / "0", "V", mesh);
    ASSERT_EQ(centres.cells.size(), static_cast<std::size_t>(mesh.cellCount));
    double total = 0;
    for (int c = 0; c < mesh.cellCount; ++c) {
        EXPECT_LT((mesh.cellCentres[c] - centres.cells[c]).norm(), 1e-13) << "cell " << c;
        EXPECT_NEAR(mesh.cellVolumes[c], volumes.cells[c], 1e-12 * volumes.cells[c]);
        total += mesh.cellVolumes[c];
    }
    // The boundary values of C are the face centres: patch values land on the right faces.
    for (std::size_t p = 0; p < mesh.patches.size(); ++p) {
        const auto& patch = mesh.patches[p];
        if (patch.type == PatchType::symmetry) {
            EXPECT_TRUE(centres.patchValues[p].empty()) << "symmetry writes no value";
            continue;
        }
        ASSERT_EQ(centres.patchValues[p].size(), static_cast<std::size_t>(patch.size));
        for (int f = 0; f < patch.size; ++f)
            EXPECT_LT((centres.patchValues[p][f] - mesh.faceCentres[patch.start + f]).norm(),
                      1e-13);
    }
    // Divergence theorem: V = (1/3) Σ_boundary x_f · S_f.
    double flux = 0;
    for (int f = mesh.internalFaceCount(); f < mesh.faceCount(); ++f)
        flux += mesh.faceCentres[f].dot(mesh.faceAreas[f]) / 3;
    EXPECT_NEAR(total, flux, 1e-14);
}

TEST_P(OpenFoamWrittenCase, PatchesAndSizes) {
    const FoamMesh mesh = readFoamMesh(data / GetParam());
    ASSERT_EQ(mesh.patches.size(), 4u);
    EXPECT_EQ(mesh.patches[0].name, "inlet");
    EXPECT_EQ(mesh.patches[0].type, PatchType::patch);
    EXPECT_EQ(mesh.patches[2].type, PatchType::wall);
    EXPECT_EQ(mesh.patches[3].type, PatchType::symmetry);
    const std::string name = GetParam();
    if (name != "dualPolyhedral") {
        EXPECT_EQ(mesh.cellCount, 12);
        EXPECT_EQ(mesh.points.size(), 36u);
        EXPECT_EQ(mesh.faceCount(), 52);
    }
}

INSTANTIATE_TEST_SUITE_P(Formats, OpenFoamWrittenCase,
                         ::testing::Values("boxAscii", "boxBinary", "boxCompressed",
                                           "dualPolyhedral"));

// Binary and compressed files hold the same numbers as the 17-digit ASCII ones, bit for bit.
TEST(FoamReader, BinaryAndCompressedEqualAscii) {
    const FoamMesh ascii = readFoamMesh(data / "boxAscii");
    for (const char* other : {"boxBinary", "boxCompressed"}) {
        const FoamMesh mesh = readFoamMesh(data / other);
        EXPECT_EQ(mesh.points, ascii.points) << other;
        EXPECT_EQ(mesh.facePoints, ascii.facePoints) << other;
        EXPECT_EQ(mesh.owner, ascii.owner) << other;
        EXPECT_EQ(mesh.neighbour, ascii.neighbour) << other;
    }
}

// OpenFOAM v1912 refuses to compress binary files, but reads them: boxBinary gzipped here
// (file by file, as `gzip`) reads bit for bit as the ASCII original.
TEST(FoamReader, CompressedBinary) {
    const auto directory =
        std::filesystem::temp_directory_path() / ("slides_binary_gz_" + std::to_string(::getpid()));
    std::filesystem::remove_all(directory);
    std::filesystem::create_directories(directory / "constant" / "polyMesh");
    for (const auto& entry :
         std::filesystem::directory_iterator(data / "boxBinary/constant/polyMesh")) {
        std::ifstream in(entry.path(), std::ios::binary);
        const std::string bytes((std::istreambuf_iterator<char>(in)),
                                std::istreambuf_iterator<char>());
        const auto target =
            directory / "constant" / "polyMesh" / (entry.path().filename().string() + ".gz");
        gzFile out = gzopen(target.c_str(), "wb");
        ASSERT_NE(out, nullptr);
        ASSERT_EQ(gzwrite(out, bytes.data(), static_cast<unsigned>(bytes.size())),
                  static_cast<int>(bytes.size()));
        gzclose(out);
    }
    const FoamMesh mesh = readFoamMesh(directory);
    const FoamMesh ascii = readFoamMesh(data / "boxAscii");
    EXPECT_EQ(mesh.points, ascii.points);
    EXPECT_EQ(mesh.facePoints, ascii.facePoints);
    std::filesystem::remove_all(directory);
}

/// A scratch case: the boxAscii mesh and one field file with the given text after the header.
class BadField : public ::testing::Test {
protected:
    void SetUp() override {
        directory_ = std::filesystem::temp_directory_path() /
                     ("slides_bad_field_" + std::to_string(::getpid()));
        std::filesystem::remove_all(directory_);
        std::filesystem::create_directories(directory_ / "0");
        std::filesystem::copy(data / "boxAscii" / "constant", directory_ / "constant",
                              std::filesystem::copy_options::recursive);
        mesh_ = readFoamMesh(directory_);
    }
    void TearDown() override { std::filesystem::remove_all(directory_); }

    void writeField(const std::string& className, const std::string& body) {
        std::ofstream(directory_ / "0" / "p")
            << "FoamFile\n{\n    format ascii;\n    class " << className << ";\n    object p;\n}\n"
            << body;
    }
    /// The error reading field p as a scalar field.
    InputError readError() {
        try {
            readFoamVolField<double>(directory_ / "0", "p", mesh_);
        } catch (const InputError& error) {
            return error;
        }
        ADD_FAILURE() << "no error";
        return InputError("", 0, "", "");
    }

    std::filesystem::path directory_;
    FoamMesh mesh_;
};

TEST_F(BadField, MissingFieldNamesTheFile) {
    const InputError error = readError();
    EXPECT_NE(error.file().find("0/p"), std::string::npos) << error.what();
    EXPECT_NE(error.reason().find("missing file"), std::string::npos) << error.what();
}

TEST_F(BadField, SizeMismatchWithTheMesh) {
    writeField("volScalarField", "internalField nonuniform List<scalar> 3 (1 2 3);\n");
    const InputError error = readError();
    EXPECT_NE(error.reason().find("size mismatch"), std::string::npos) << error.what();
    EXPECT_NE(error.reason().find("expected 12"), std::string::npos) << error.what();
    EXPECT_EQ(error.line(), 7);
}

TEST_F(BadField, BadTokenWithItsLine) {
    writeField("volScalarField",
               "internalField nonuniform List<scalar> 12\n(\n1 2 3\n4 x 6 7 8 9 10 11 12\n);\n");
    const InputError error = readError();
    EXPECT_NE(error.reason().find("bad token 'x"), std::string::npos) << error.what();
    EXPECT_EQ(error.line(), 10);
}

TEST_F(BadField, WrongClass) {
    writeField("volVectorField", "internalField uniform (0 0 0);\n");
    EXPECT_NE(readError().reason().find("expected volScalarField"), std::string::npos);
}

TEST_F(BadField, UniformAndPatchValues) {
    writeField("volScalarField", "dimensions [0 2 -2 0 0 0 0];\ninternalField uniform 3.5;\n"
                                 "boundaryField\n{\n #includeEtc \"caseDicts/setConstraintTypes\"\n"
                                 " inlet { type fixedValue; value uniform 2; }\n"
                                 " outlet { type zeroGradient; }\n \"(walls|sides)\" { type "
                                 "calculated; value uniform 0; }\n}\n");
    const auto field = readFoamVolField<double>(directory_ / "0", "p", mesh_);
    EXPECT_EQ(field.cells, std::vector<double>(12, 3.5));
    EXPECT_EQ(field.patchValues[0], std::vector<double>(4, 2.0));
    EXPECT_TRUE(field.patchValues[1].empty());
}

// Numbers read as strtod reads them, bit for bit: the fast path (std::from_chars) and what it
// leaves to strtod (a '+' sign, hexadecimal, subnormals).
TEST_F(BadField, NumbersAreReadAsStrtodReadsThem) {
    const std::vector<std::string> numbers{"+1.5",
                                           "0x1p-3",
                                           "4.9e-324",
                                           "1e-310",
                                           "0.1",
                                           "-2.5e-3",
                                           "1.7976931348623157e308",
                                           "3",
                                           "-0",
                                           "123456789.123456789",
                                           "2.2250738585072014e-308",
                                           "7e-1"};
    std::string list = "internalField nonuniform List<scalar> 12\n(\n";
    for (const std::string& number : numbers) list += number + "\n";
    writeField("volScalarField", list + ");\nboundaryField { \".*\" { type zeroGradient; } }\n");
    const auto field = readFoamVolField<double>(directory_ / "0", "p", mesh_);
    for (std::size_t i = 0; i < numbers.size(); ++i) {
        const double expected = std::strtod(numbers[i].c_str(), nullptr);
        EXPECT_EQ(std::memcmp(&field.cells[i], &expected, sizeof expected), 0) << numbers[i];
    }
}

// A time-dependent inlet as pimpleFoam writes it (foamCases/transientJet): the Function1's
// coefficients are a sub-dictionary of entries, skipped up to the patch's value.
TEST_F(BadField, PatchWithSubDictionaryEntries) {
    writeField("volScalarField",
               "internalField uniform 1;\nboundaryField\n{\n inlet\n {\n"
               "  type uniformFixedValue;\n  uniformValue sine;\n  uniformValueCoeffs\n  {\n"
               "   t0 0;\n   amplitude constant -0.3;\n   level constant 1.5;\n  }\n"
               "  value uniform 2.25;\n }\n \"(outlet|walls|sides)\" { type zeroGradient; }\n}\n");
    const auto field = readFoamVolField<double>(directory_ / "0", "p", mesh_);
    EXPECT_EQ(field.patchValues[0], std::vector<double>(4, 2.25));
}

// A noSlip wall writes no value (simpleFoam's U of impingingJet's plate): it is zero, not left
// to the cells as zeroGradient (which put U ≈ 0.7 m/s at the plate's points in the jet).
TEST_F(BadField, NoSlipWallIsAtRest) {
    writeField("volVectorField", "internalField uniform (1 2 3);\nboundaryField\n{\n"
                                 " walls { type noSlip; }\n \"(inlet|outlet)\" { type "
                                 "zeroGradient; }\n sides { type symmetry; }\n}\n");
    const auto field = readFoamVolField<Vec3>(directory_ / "0", "p", mesh_);
    EXPECT_EQ(field.patchValues[2], std::vector<Vec3>(12, Vec3::Zero()));
    EXPECT_TRUE(field.patchValues[1].empty());
}

// Bad values in the carrier are reported with the cell, never sampled: NaN (a diverged
// solution writes "nan"), infinity, and k, ε, T outside their physical bounds.
TEST_F(BadField, NonFiniteValuesNameTheCellOrFace) {
    writeField("volScalarField",
               "internalField nonuniform List<scalar> 12\n(\n1 2 3 4 5 nan 7 8 9 10 11 12\n);\n");
    InputError error = readError();
    EXPECT_NE(error.file().find("0/p"), std::string::npos) << error.what();
    EXPECT_NE(error.reason().find("cell 5 of internalField holds nan"), std::string::npos)
        << error.what();
    writeField("volScalarField", "internalField uniform 1;\nboundaryField\n{\n"
                                 " inlet { type fixedValue; value uniform inf; }\n}\n");
    error = readError();
    EXPECT_NE(error.reason().find("face 0 of patch inlet holds inf"), std::string::npos)
        << error.what();
}

TEST_F(BadField, NegativeTurbulenceEnergyNamesTheCell) {
    const std::string zeroGradient = "boundaryField { \".*\" { type zeroGradient; } }\n";
    std::ofstream(directory_ / "0" / "U")
        << "FoamFile\n{\n    format ascii;\n    class volVectorField;\n    object U;\n}\n"
        << "dimensions [0 1 -1 0 0 0 0];\ninternalField uniform (1 0 0);\n"
        << zeroGradient;
    std::ofstream(directory_ / "0" / "k")
        << "FoamFile\n{\n    format ascii;\n    class volScalarField;\n    object k;\n}\n"
        << "dimensions [0 2 -2 0 0 0 0];\n"
        << "internalField nonuniform List<scalar> 12\n(\n1 2 3 4 5 6 7 8 9 -0.25 11 12\n);\n"
        << zeroGradient;
    try {
        FoamCarrier carrier(directory_, {});
        ADD_FAILURE() << "a negative k was accepted";
    } catch (const InputError& error) {
        EXPECT_NE(error.file().find("0/k"), std::string::npos) << error.what();
        EXPECT_NE(error.reason().find("cell 9 has k = -0.25, which must be at least 0"),
                  std::string::npos)
            << error.what();
    }
}

TEST_F(BadField, TimeDirectories) {
    for (const char* time : {"0.5", "10", "2e-1"}) {
        std::filesystem::create_directories(directory_ / time);
        std::ofstream(directory_ / time / "U") << "";
    }
    std::filesystem::create_directories(directory_ / "20"); // no U: not a result
    EXPECT_EQ(foamTimeDirectory(directory_, "latestTime").filename(), "10");
    EXPECT_EQ(foamTimeDirectory(directory_, "0.2").filename(), "2e-1");
    EXPECT_EQ(foamTimeDirectory(directory_, "0.50").filename(), "0.5");
    EXPECT_THROW(foamTimeDirectory(directory_, "7"), InputError);
    EXPECT_THROW(foamTimeDirectory(directory_, "soon"), InputError);
}

} // namespace
} // namespace slides
