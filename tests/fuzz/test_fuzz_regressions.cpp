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

// The seeds read back whole: the one fuzz::writeSeedCheckpoint writes now and the one kept in
// tests/fuzz/regressions/checkpoint/seed-small, so the mutations start from a checkpoint the
// reader accepts (a stale seed would test only the first refusal).
TEST(CheckpointFuzzRegressions, SeedsReadBack) {
    const fs::path directory =
        fs::temp_directory_path() / ("slides-checkpoint-seed-" + std::to_string(::getpid()));
    for (const bool kept : {false, true}) {
        SCOPED_TRACE(kept ? "kept seed" : "seed written now");
        fs::remove_all(directory);
        fs::create_directories(directory);
        if (kept)
            fs::copy_file(fs::path(SLIDES_SOURCE_DIR) /
                              "tests/fuzz/regressions/checkpoint/seed-small",
                          directory / checkpointFileName);
        else
            fuzz::writeSeedCheckpoint(directory);
        const CheckpointState state = readCheckpoint(directory, fuzz::checkpointFingerprint);
        EXPECT_EQ(state.cloud.size(), 5u);
        EXPECT_EQ(state.cloud.modelState.size(), 15u);
        EXPECT_EQ(state.cloud.eddy.at(4).count, 4u);
        EXPECT_EQ(state.arrivals.size(), 2u);
        EXPECT_EQ(state.springs.first.size(), 2u);
        EXPECT_EQ(state.frames.size(), 3u);
        EXPECT_EQ(state.times.steppingSeconds, 1.25);
    }
    fs::remove_all(directory);
}

// Every kept input, and every byte of the seed changed in turn (0x5a flipped in, at a stride
// that reaches each part of the file: superblock, object headers, B-trees, heaps, chunks): a
// clean refusal (InputError) or a state without NaN, never a crash.
TEST(CheckpointFuzzRegressions, MutatedCheckpointsAreRefusedOrRead) {
    const auto inputs = keptInputs("checkpoint");
    ASSERT_FALSE(inputs.empty()) << "no inputs in tests/fuzz/regressions/checkpoint";
    for (const auto& input : inputs) {
        SCOPED_TRACE(input.filename().string());
        EXPECT_NO_THROW(fuzz::readCheckpointBytes(bytesOf(input)));
    }
    const std::string seed =
        bytesOf(fs::path(SLIDES_SOURCE_DIR) / "tests/fuzz/regressions/checkpoint/seed-small");
    ASSERT_GT(seed.size(), 1000u);
    for (std::size_t at = 0; at < seed.size(); at += 7) {
        std::string mutated = seed;
        mutated[at] ^= 0x5a;
        SCOPED_TRACE("byte " + std::to_string(at));
        EXPECT_NO_THROW(fuzz::readCheckpointBytes(mutated));
    }
    for (const std::size_t length : {std::size_t{0}, std::size_t{8}, seed.size() / 2})
        EXPECT_NO_THROW(fuzz::readCheckpointBytes(seed.substr(0, length)));
}

INSTANTIATE_TEST_SUITE_P(Meshes, FoamFuzzRegressions, testing::Values("boxAscii", "boxBinary"),
                         [](const auto& info) { return std::string(info.param); });

} // namespace
} // namespace slides
