// ctest-labels: foundation config
// summary.json's settings report the dictionary's choices by their names (config/scene_json.h,
// sceneSettings): for the default spray case with each carrier type and each injection mode
// in turn, the reported carrier.type and injection.mode are the dictionary's words. (The
// summary once reported carrier `none` as "foamField" and injection `lattice` as "allAtStart".)
#include "slides/config/dictionary.h"
#include "slides/config/scene_json.h"
#include "slides/config/scene_reader.h"

#include "../support/case_runs.h"

#include <gtest/gtest.h>

#include <string>

namespace slides {
namespace {

/// The settings summary.json reports for the default case with `changes` appended (a repeated
/// sub-dictionary merges, a repeated keyword replaces).
nlohmann::json settingsWith(const std::string& changes) {
    const auto file = test::defaultCase / "constant" / "slidesProperties";
    const Dictionary dictionary =
        Dictionary::parseString(test::slurp(file) + "\n" + changes, file.string());
    return sceneSettings(sceneFromDictionary(dictionary, test::defaultCase));
}

struct CarrierCase {
    const char* type;
    const char* changes;
};

class SummaryCarrierType : public testing::TestWithParam<CarrierCase> {};

TEST_P(SummaryCarrierType, ReportsTheDictionarysType) {
    const nlohmann::json settings = settingsWith(GetParam().changes);
    EXPECT_EQ(settings["carrier"]["type"], GetParam().type);
}

INSTANTIATE_TEST_SUITE_P(
    EachCarrier, SummaryCarrierType,
    testing::Values(
        CarrierCase{"analyticJet", ""},
        CarrierCase{
            "roundLaminarJet",
            "carrier { type roundLaminarJet; roundLaminarJetCoeffs { nozzleVelocity 50; } }"},
        CarrierCase{"foamField", "carrier { type foamField; }"},
        CarrierCase{"none", "carrier { type none; }"}),
    [](const auto& info) { return std::string(info.param.type); });

struct InjectionCase {
    const char* mode;
    const char* changes;
};

class SummaryInjectionMode : public testing::TestWithParam<InjectionCase> {};

TEST_P(SummaryInjectionMode, ReportsTheDictionarysMode) {
    const nlohmann::json settings = settingsWith(GetParam().changes);
    EXPECT_EQ(settings["injection"]["mode"], GetParam().mode);
}

INSTANTIATE_TEST_SUITE_P(
    EachMode, SummaryInjectionMode,
    testing::Values(InjectionCase{"rate", ""},
                    InjectionCase{"allAtStart", "injection { mode allAtStart; }"},
                    // 20³ sites hold the case's 8000 particles, inside its domain box.
                    InjectionCase{"lattice",
                                  "injection { mode lattice; latticeCoeffs { origin (0.01 -0.01 "
                                  "-0.01); spacing 1e-3; sites (20 20 20); velocitySpread 0; } }"}),
    [](const auto& info) { return std::string(info.param.mode); });

TEST(SummaryElectromagnetic, ReportsTheFieldsAndTheChargeModel) {
    // Off by default; on, the model, fields and charge model as given (physics/electromagnetic.h).
    EXPECT_EQ(settingsWith("")["physics"]["electromagnetic"]["model"], "none");
    const nlohmann::json fields = settingsWith(
        "physics { electromagnetic { model lorentz; B (0 0 0.25); charge { model "
        "surface; value 2e-5; oppositeSignFraction 0.25; } } }")["physics"]["electromagnetic"];
    EXPECT_EQ(fields["model"], "lorentz");
    EXPECT_EQ(fields["B"], nlohmann::json::array({0.0, 0.0, 0.25}));
    EXPECT_EQ(fields["charge"]["model"], "surface");
    EXPECT_EQ(fields["charge"]["value"], 2e-5);
    EXPECT_EQ(fields["charge"]["oppositeSignFraction"], 0.25);
    EXPECT_EQ(fields["coulomb"]["model"], "none");
}

TEST(SummaryElectromagnetic, ReportsTheCoilsAndTheMagnetisation) {
    // physics/current_loop.h and physics/magnetic_force.h: each coil by its name, the axis made
    // a unit vector; the magnetisation model and susceptibility as given.
    EXPECT_EQ(settingsWith("")["physics"]["electromagnetic"]["magnetisation"]["model"], "none");
    const nlohmann::json fields =
        settingsWith("physics { electromagnetic { model lorentz; coils { upper { centre (0 0 "
                     "0.1); axis (0 0 2); radius 0.05; current 2000; } lower { radius 0.02; "
                     "current -300; } } magnetisation { model linear; susceptibility 0.25; } } "
                     "}")["physics"]["electromagnetic"];
    EXPECT_EQ(fields["coils"]["upper"]["centre"], nlohmann::json::array({0.0, 0.0, 0.1}));
    EXPECT_EQ(fields["coils"]["upper"]["axis"], nlohmann::json::array({0.0, 0.0, 1.0}));
    EXPECT_EQ(fields["coils"]["upper"]["radius"], 0.05);
    EXPECT_EQ(fields["coils"]["upper"]["current"], 2000.0);
    EXPECT_EQ(fields["coils"]["lower"]["centre"], nlohmann::json::array({0.0, 0.0, 0.0}));
    EXPECT_EQ(fields["coils"]["lower"]["current"], -300.0);
    EXPECT_EQ(fields["magnetisation"]["model"], "linear");
    EXPECT_EQ(fields["magnetisation"]["susceptibility"], 0.25);
}

TEST(SummaryElectromagnetic, ReportsTheCoulombTruncation) {
    // physics/coulomb.h: the model, cut-off and relative permittivity as given.
    const nlohmann::json coulomb =
        settingsWith("physics { electromagnetic { model lorentz; coulomb { model shifted; cutoff "
                     "2e-3; permittivity 1.5; } } }")["physics"]["electromagnetic"]["coulomb"];
    EXPECT_EQ(coulomb["model"], "shifted");
    EXPECT_EQ(coulomb["cutoff"], 2e-3);
    EXPECT_EQ(coulomb["permittivity"], 1.5);
}

} // namespace
} // namespace slides
