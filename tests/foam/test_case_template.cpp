// ctest-labels: config injection
// foam-cases: impingingJet impingingJet3d planarJet transientJet
// `slides-track --init CASE` (config/case_template.h) writes a constant/slidesProperties that
// runs as written, for every shipped case: the solved OpenFOAM runs (wedge, 3-D and 2-D meshes)
// get their patch names, their mesh's box (1 % of its largest extent wider on every side) as
// the domain and their inlet as the injection; the cases without a mesh get the analytic jet.
// Every key written is declared in the key table and carries its doc line as a comment.
// Each written case passes --check and runs; numbers are checked against the mesh's points
// (9 significant digits written: relative tolerance 1e-8). A case dictionary that exists is
// never overwritten.
#include "../support/case_runs.h"

#include "slides/carrier/foam_mesh.h"
#include "slides/config/dictionary.h"
#include "slides/config/scene_keys.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <fstream>
#include <regex>
#include <sstream>

namespace slides {
namespace {

namespace fs = std::filesystem;

/// The words of every `//` comment of text, one space apart.
std::string commentWords(const std::string& text) {
    std::istringstream lines(text);
    std::string line, words;
    while (std::getline(lines, line)) {
        const auto at = line.find_first_not_of(' ');
        if (at != std::string::npos && line.compare(at, 3, "// ") == 0)
            words += line.substr(at + 3) + " ";
    }
    return words;
}

/// Every key of dictionary is declared in the key table and written under its doc line.
void expectEveryKeyDocumented(const Dictionary& dictionary, const std::string& comments) {
    for (const std::string& key : dictionary.keys()) {
        const std::string path = dictionary.keyPath(key);
        const KeyDeclaration* declaration = findSceneKey(path);
        ASSERT_NE(declaration, nullptr) << path;
        EXPECT_NE(comments.find(declaration->doc), std::string::npos) << path;
        if (dictionary.isDict(key)) expectEveryKeyDocumented(dictionary.subDict(key), comments);
    }
}

/// Writes the template into scratch's case, then checks it (--check) and runs it briefly; both
/// must succeed and the short run inject particles. Returns the written dictionary.
Dictionary initCheckAndRun(const test::ScratchDirectory& scratch) {
    const fs::path log = scratch.path / "log";
    const fs::path file = scratch.path / "constant" / "slidesProperties";
    EXPECT_EQ(test::runCli("--init " + scratch.path.string(), log), 0) << test::slurp(log);
    EXPECT_NE(test::slurp(log).find("wrote " + file.string()), std::string::npos)
        << test::slurp(log);
    EXPECT_EQ(test::runCli(scratch.path.string() + " --check", log), 0) << test::slurp(log);
    EXPECT_FALSE(fs::exists(scratch.path / "slides")) << "--check must write nothing";
    EXPECT_EQ(test::runCli(scratch.path.string() + " --quiet --threads 2 --end-time 1e-3", log), 0)
        << test::slurp(log);
    const auto summary =
        nlohmann::json::parse(test::slurp(scratch.path / "slides" / "summary.json"));
    EXPECT_GT(summary["particles"]["injected"].get<long>(), 0);
    Dictionary dictionary = Dictionary::parseFile(file);
    expectEveryKeyDocumented(dictionary, commentWords(test::slurp(file)));
    return dictionary;
}

struct SolvedRun {
    const char* run;
    const char* inlet;  ///< the patch particles enter through
    bool wedge;         ///< axisymmetric about x: the box is the wedge swept about it
    double inletRadius; ///< the nozzle disc's radius from the blockMeshDict; 0: a patch injector
};

class CaseTemplateOfSolvedRun : public ::testing::TestWithParam<SolvedRun> {};

TEST_P(CaseTemplateOfSolvedRun, HoldsTheMeshAndRunsAsWritten) {
    const SolvedRun& param = GetParam();
    test::ScratchDirectory scratch(std::string("caseTemplate-") + param.run);
    test::copySolvedRun(param.run, scratch.path);
    fs::remove(scratch.path / "constant" / "slidesProperties");
    const Dictionary dictionary = initCheckAndRun(scratch);
    const std::string text = test::slurp(scratch.path / "constant" / "slidesProperties");
    EXPECT_EQ(text.rfind("/*", 0), 0u) << "the OpenFOAM banner first";
    ASSERT_NE(dictionary.header(), nullptr) << "FoamFile header";
    EXPECT_EQ(dictionary.header()->word("object"), "slidesProperties");
    EXPECT_EQ(dictionary.subDict("carrier").word("type"), "foamField");

    // Every patch named in the surfaces section: a wall as a surface, the others as comments.
    const FoamMesh mesh = readFoamMesh(scratch.path);
    const Dictionary& surfaces = dictionary.subDict("surfaces");
    for (const FoamPatch& patch : mesh.patches) {
        if (patch.type == PatchType::wall)
            EXPECT_TRUE(surfaces.isDict(patch.name)) << patch.name;
        else
            EXPECT_NE(text.find("    // " + patch.name + " ("), std::string::npos) << patch.name;
    }

    // The domain: the mesh's points' box (a wedge's swept about x), widened by 1 % of its
    // largest extent.
    Vec3 low = mesh.boundsMin, high = mesh.boundsMax;
    if (param.wedge) {
        double radius = 0;
        for (const Vec3& point : mesh.points) radius = std::max(radius, point.tail<2>().norm());
        low.tail<2>().setConstant(-radius);
        high.tail<2>().setConstant(radius);
    }
    const double margin = 0.01 * (high - low).maxCoeff();
    const Vec3 domainMin = dictionary.subDict("domain").vector("min");
    const Vec3 domainMax = dictionary.subDict("domain").vector("max");
    for (int j = 0; j < 3; ++j) {
        EXPECT_NEAR(domainMin[j], low[j] - margin, 1e-8 * margin * 100) << j;
        EXPECT_NEAR(domainMax[j], high[j] + margin, 1e-8 * margin * 100) << j;
    }

    // The inlet: a patch injector (3-D, wedge), or a nozzle disc on it (2-D).
    if (param.inletRadius > 0) {
        const Dictionary& nozzle = dictionary.subDict("nozzle");
        EXPECT_NEAR(nozzle.scalar("radius"), param.inletRadius, 1e-8 * param.inletRadius);
        EXPECT_NEAR(nozzle.vector("axis").dot(Vec3::UnitX()), 1, 1e-12) << "into the mesh";
        EXPECT_NE(text.find("On the inlet patch '" + std::string(param.inlet) + "'"),
                  std::string::npos);
    } else {
        EXPECT_EQ(dictionary.subDict("injectors")
                      .subDict(param.inlet)
                      .subDict("patchCoeffs")
                      .word("patch"),
                  param.inlet);
    }
}

// impingingJet: 2 mm nozzle at x = 0 on the axis, plate at x = 0.06 m, r ≤ 0.04 m; the nozzle
// patch is found by its inflow (25 m/s, the entrainment's is slower). planarJet: the half slot
// y ∈ [0, 1 mm] beside the symmetry plane, so the disc (the slot's line) has radius 0.5 mm.
// transientJet: its latest level; of the two slot halves (2 mm each, the same inflow at t = 0.2 s,
// where the sine of the pulse is zero) the first patch, slotLower.
INSTANTIATE_TEST_SUITE_P(ShippedRuns, CaseTemplateOfSolvedRun,
                         ::testing::Values(SolvedRun{"impingingJet", "nozzle", true, 0},
                                           SolvedRun{"impingingJet3d", "nozzle", false, 0},
                                           SolvedRun{"planarJet", "slot", false, 0.5e-3},
                                           SolvedRun{"transientJet", "slotLower", false, 1e-3}),
                         [](const auto& info) { return std::string(info.param.run); });

TEST(CaseTemplate, OnAWedgeOnlyAWallAcrossTheAxisBecomesAPlane) {
    // The plate x = 0.06 m is a plane of the swept region; the cylinder r = 0.04 m (`outer`,
    // made a wall here) is one plane in the wedge but not about the axis: it stays an exit.
    test::ScratchDirectory scratch("caseTemplate-plate");
    test::copySolvedRun("impingingJet", scratch.path);
    fs::remove(scratch.path / "constant" / "slidesProperties");
    const fs::path boundary = scratch.path / "constant" / "polyMesh" / "boundary";
    std::string patches = test::slurp(boundary);
    patches = std::regex_replace(patches, std::regex(R"((outer\s*\{\s*type\s+)patch;)"), "$1wall;");
    std::ofstream(boundary) << patches;
    ASSERT_EQ(test::runCli("--init " + scratch.path.string(), scratch.path / "log"), 0);
    const std::string text = test::slurp(scratch.path / "constant" / "slidesProperties");
    const Dictionary surfaces =
        Dictionary::parseFile(scratch.path / "constant" / "slidesProperties").subDict("surfaces");
    const Dictionary& plate = surfaces.subDict("plate");
    EXPECT_EQ(plate.word("type"), "plane");
    EXPECT_NEAR((plate.vector("point") - Vec3(0.06, 0, 0)).norm(), 0, 1e-12)
        << "the plate of the blockMeshDict, where it meets the axis";
    EXPECT_NEAR(plate.vector("normal").x(), -1, 1e-12) << "into the gas";
    EXPECT_FALSE(surfaces.has("outer"));
    EXPECT_NE(text.find("// outer (wall): a wall of a wedge or 2-D mesh that is not one plane"),
              std::string::npos);
}

/// The shipped cases without a mesh: the analytic jet's template.
class CaseTemplateWithoutMesh : public ::testing::TestWithParam<const char*> {};

TEST_P(CaseTemplateWithoutMesh, IsTheAnalyticJetAndRunsAsWritten) {
    test::ScratchDirectory scratch(std::string("caseTemplate-") + GetParam());
    fs::copy(test::sourceDir / "foamCases" / GetParam(), scratch.path,
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    fs::remove(scratch.path / "constant" / "slidesProperties");
    const Dictionary dictionary = initCheckAndRun(scratch);
    EXPECT_EQ(dictionary.subDict("carrier").word("type"), "analyticJet");
}

INSTANTIATE_TEST_SUITE_P(ShippedCases, CaseTemplateWithoutMesh,
                         ::testing::Values("analyticSpray", "erosiveJet", "pulsedJet",
                                           "sprayDeposition"));

TEST(CaseTemplate, AnalyticJetCarriesEveryParticleToThePlate) {
    // The whole run as written: the 10 µm particles (Stokes time 2.4 ms, 25 m/s jet) follow
    // the jet to the plate 60 mm away; each of the 1000 injected is counted once.
    test::ScratchDirectory scratch("caseTemplate-wholeRun");
    ASSERT_EQ(test::runCli("--init " + scratch.path.string(), scratch.path / "log"), 0);
    ASSERT_EQ(test::runCli(scratch.path.string() + " --quiet --threads 2", scratch.path / "log"), 0)
        << test::slurp(scratch.path / "log");
    const auto particles =
        nlohmann::json::parse(test::slurp(scratch.path / "slides" / "summary.json"))["particles"];
    EXPECT_EQ(particles["injected"].get<long>(), 1000);
    EXPECT_EQ(particles["arrived"]["target"].get<long>(), 1000);
}

TEST(CaseTemplate, AnExistingDictionaryIsNeverOverwritten) {
    test::ScratchDirectory scratch("caseTemplate-exists");
    const fs::path file = scratch.path / "constant" / "slidesProperties";
    const std::string own = "// the user's own dictionary\n";
    std::ofstream(file) << own;
    const fs::path log = scratch.path / "log";
    EXPECT_EQ(test::runCli("--init " + scratch.path.string(), log), 2);
    const std::string message = test::slurp(log);
    EXPECT_NE(message.find(file.string() + ": exists already; --init never overwrites"),
              std::string::npos)
        << message;
    EXPECT_EQ(test::slurp(file), own) << "the file must be unchanged";
}

TEST(CaseTemplate, AnOpenFoamCaseWithoutItsMeshIsRefused) {
    // foamCases/planarJet as shipped: blockMeshDict and controlDict, no mesh or solution yet.
    test::ScratchDirectory scratch("caseTemplate-unsolved");
    fs::copy(test::sourceDir / "foamCases" / "planarJet", scratch.path,
             fs::copy_options::recursive | fs::copy_options::overwrite_existing);
    const fs::path log = scratch.path / "log";
    EXPECT_EQ(test::runCli("--init " + scratch.path.string(), log), 2);
    EXPECT_NE(test::slurp(log).find((scratch.path / "constant" / "polyMesh").string() +
                                    ": missing: an OpenFOAM case (system/controlDict) without "
                                    "its mesh; run its Allrun"),
              std::string::npos)
        << test::slurp(log);
    EXPECT_FALSE(fs::exists(scratch.path / "constant" / "slidesProperties"));
}

TEST(CaseTemplate, ACaseThatIsNotADirectoryIsRefused) {
    test::ScratchDirectory scratch("caseTemplate-notDirectory");
    const fs::path notADirectory = scratch.path / "constant" / "file";
    std::ofstream(notADirectory) << "x\n";
    EXPECT_EQ(test::runCli("--init " + notADirectory.string(), scratch.path / "log"), 2);
    EXPECT_EQ(test::runCli("--init " + (scratch.path / "missing").string(), scratch.path / "log"),
              2);
    EXPECT_FALSE(fs::exists(scratch.path / "missing"));
}

} // namespace
} // namespace slides
