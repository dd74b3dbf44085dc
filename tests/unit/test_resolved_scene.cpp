// ctest-labels: foundation config run robustness
// The resolve step (run/resolved_scene.h) on the default spray case: the command line's
// overrides land in the resolved scene, the scene analysis's time step is taken where none is
// given (and a given one is kept), and a bad override is one InputError naming its option.
#include "slides/core/error.h"
#include "slides/run/resolved_scene.h"

#include "../support/case_runs.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <regex>
#include <string>
#include <unistd.h>

namespace slides {
namespace {

SceneOverrides overrides(std::optional<double> endTime, std::optional<double> dt,
                         std::optional<std::string> time = std::nullopt) {
    SceneOverrides result;
    result.endTime = endTime;
    result.dt = dt;
    result.time = time;
    return result;
}

TEST(ResolvedScene, OverridesLandInTheResolvedScene) {
    const ResolvedScene resolved = resolveScene(test::defaultCase, overrides(0.01, 2e-5));
    EXPECT_EQ(resolved.scene.time.endTime, 0.01);
    EXPECT_EQ(resolved.scene.time.dt, 2e-5);
    EXPECT_TRUE(resolved.analysis.timeStepGiven);
    ASSERT_NE(resolved.carrier, nullptr);
}

TEST(ResolvedScene, WithoutDtTheAnalysisTimeStepIsTaken) {
    // The default case without its time.dt line: the analysis chooses the step.
    const auto directory = std::filesystem::temp_directory_path() /
                           ("slides-resolved-scene-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory / "constant");
    const std::string dictionary =
        std::regex_replace(test::slurp(test::defaultCase / "constant" / "slidesProperties"),
                           std::regex("\\n *dt +[^;]*;"), "\n");
    std::ofstream(directory / "constant" / "slidesProperties") << dictionary;
    const ResolvedScene resolved = resolveScene(directory, {});
    std::filesystem::remove_all(directory);
    EXPECT_FALSE(resolved.analysis.timeStepGiven);
    EXPECT_GT(resolved.analysis.suggestedTimeStep, 0);
    EXPECT_EQ(resolved.scene.time.dt, resolved.analysis.suggestedTimeStep);
}

// A refused --dt or --end-time names the key it overrides, at its line of the dictionary
// (time.dt on line 84 of the default case, time.endTime on 85), and the option's value.
TEST(ResolvedScene, BadOverridesAreInputErrorsNamingTheKeyTheyOverride) {
    const auto errorOf = [](const SceneOverrides& overrides) {
        try {
            resolveScene(test::defaultCase, overrides);
        } catch (const InputError& error) {
            return std::string(error.what());
        }
        return std::string("no error");
    };
    const std::string dictionary = (test::defaultCase / "constant/slidesProperties").string();
    EXPECT_EQ(errorOf(overrides(-1.0, std::nullopt)),
              dictionary + ":85: key 'time.endTime': --end-time -1 on the command line must be "
                           "positive");
    EXPECT_EQ(errorOf(overrides(std::nullopt, 0.0)),
              dictionary + ":84: key 'time.dt': --dt 0 on the command line must be positive");
    EXPECT_EQ(errorOf(overrides(std::nullopt, -std::numeric_limits<double>::quiet_NaN())),
              dictionary + ":84: key 'time.dt': --dt -nan on the command line must be positive");
    EXPECT_EQ(errorOf(overrides(1e-3, 2e-3)),
              dictionary + ":84: key 'time.dt': --dt 0.002 on the command line is longer than "
                           "time.endTime 0.001 s");
    EXPECT_EQ(errorOf(overrides(1e-6, std::nullopt)),
              dictionary + ":85: key 'time.endTime': --end-time 1e-06 on the command line is "
                           "shorter than time.dt 1e-05 s");
    EXPECT_EQ(errorOf(overrides(std::nullopt, std::nullopt, "latestTime")),
              "command line: key '--time': only an OpenFOAM carrier (foamField) has time "
              "directories"); // an analytic carrier
}

} // namespace
} // namespace slides
