// ctest-labels: io robustness
// Replays every input kept in tests/fuzz/regressions/<target>/ (inputs on which a reader once
// crashed, hung or misbehaved; tools/fuzz/run adds them) through the same entry point as the
// fuzz target. Each must end in success or an InputError naming the file: under tools/sanitize
// also without any sanitizer report.
#include "../support/fuzz_entries.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace slides {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> keptInputs(const std::string& target) {
    std::vector<fs::path> inputs;
    const fs::path folder = fs::path(SLIDES_SOURCE_DIR) / "tests" / "fuzz" / "regressions" / target;
    if (!fs::exists(folder)) return inputs;
    for (const auto& entry : fs::directory_iterator(folder)) inputs.push_back(entry.path());
    std::sort(inputs.begin(), inputs.end());
    return inputs;
}

std::string bytesOf(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

TEST(FuzzRegressions, DictionaryInputsEndInSuccessOrAnInputError) {
    const auto inputs = keptInputs("dictionary");
    ASSERT_FALSE(inputs.empty());
    for (const auto& input : inputs) {
        SCOPED_TRACE(input.filename().string());
        EXPECT_NO_THROW(fuzz::readDictionaryText(bytesOf(input)));
    }
}

class FoamFuzzRegressions : public testing::TestWithParam<const char*> {};

TEST_P(FoamFuzzRegressions, CaseInputsEndInSuccessOrAnInputError) {
    // Seeds (the case's own files) and the inputs tools/fuzz/run kept because they failed.
    const auto inputs = keptInputs(std::string("foam_") + GetParam());
    ASSERT_FALSE(inputs.empty()) << "no inputs in tests/fuzz/regressions/foam_" << GetParam();
    for (const auto& input : inputs) {
        SCOPED_TRACE(input.filename().string());
        EXPECT_NO_THROW(fuzz::readFoamCaseWithReplacedFile(bytesOf(input), GetParam()));
    }
}

INSTANTIATE_TEST_SUITE_P(Meshes, FoamFuzzRegressions, testing::Values("boxAscii", "boxBinary"),
                         [](const auto& info) { return std::string(info.param); });

} // namespace
} // namespace slides
