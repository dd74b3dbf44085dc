// ctest-labels: robustness restart io
// What a checkpoint (io/checkpoint.h) holds and what a restart does with the output directory:
// every dataset of checkpoint.h5 carries a checksum, so a byte flipped in any one of them is
// refused (exit status 2, the message naming the file and the dataset); the checkpoint holds no
// copy of the frames, so its size does not grow with them; a restart removes the temporaries
// that killed runs left; and summary.json reports the whole run's steps and times, every segment
// summed. The default spray to 4 ms (3200 particles injected, the first arrived at 2.6 ms),
// checkpointed at its last step.
#include "../support/case_runs.h"
#include "slides/io/hdf5_file.h"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <nlohmann/json.hpp>

#include <fstream>
#include <string>
#include <vector>

#include <sys/wait.h>
#include <unistd.h>

namespace slides {
namespace {

namespace fs = std::filesystem;
using test::runCli;
using test::slurp;

/// The default case with output.interval `interval`, run to 4 ms (400 steps) with a
/// checkpoint at its last step.
struct CheckpointedSpray : test::ScratchDirectory {
    explicit CheckpointedSpray(const std::string& name, const std::string& interval = "5e-4")
        : test::ScratchDirectory(name) {
        std::ofstream(path / "constant" / "slidesProperties")
            << "#include \"" << (test::defaultCase / "constant" / "slidesProperties").string()
            << "\"\noutput { interval " << interval << "; }\n";
        status = runCli(path.string() + " --quiet --end-time 0.004 --checkpoint-every 400",
                        path / "log");
    }
    fs::path output() const { return path / "slides"; }
    fs::path checkpoint() const { return output() / "checkpoint.h5"; }
    int status = -1;
};

/// The datasets of an HDF5 file that hold data, by path.
std::vector<std::string> datasetsWithData(const fs::path& file) {
    std::vector<std::string> paths;
    const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const auto visit = [](hid_t root, const char* name, const H5O_info_t* info,
                          void* found) -> herr_t {
        if (info->type != H5O_TYPE_DATASET) return 0;
        const hid_t dataset = H5Dopen2(root, name, H5P_DEFAULT);
        if (H5Dget_storage_size(dataset) > 0)
            static_cast<std::vector<std::string>*>(found)->push_back(std::string("/") + name);
        H5Dclose(dataset);
        return 0;
    };
    H5Ovisit(id, H5_INDEX_NAME, H5_ITER_INC, visit, &paths);
    H5Fclose(id);
    return paths;
}

/// Flips one byte in the middle of the first stored chunk of dataset in file.
void flipByteIn(const fs::path& file, const std::string& dataset) {
    haddr_t address = 0;
    hsize_t size = 0;
    {
        const hid_t id = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        const hid_t data = H5Dopen2(id, dataset.c_str(), H5P_DEFAULT);
        const hid_t space = H5Dget_space(data);
        ASSERT_GE(H5Dget_chunk_info(data, space, 0, nullptr, nullptr, &address, &size), 0)
            << dataset << " is not chunked";
        H5Sclose(space);
        H5Dclose(data);
        H5Fclose(id);
    }
    ASSERT_GT(size, 0u) << dataset;
    std::fstream bytes(file, std::ios::in | std::ios::out | std::ios::binary);
    bytes.seekg(static_cast<std::streamoff>(address + size / 2));
    const char byte = static_cast<char>(bytes.get());
    bytes.seekp(static_cast<std::streamoff>(address + size / 2));
    bytes.put(static_cast<char>(byte ^ 0x5a));
}

TEST(CheckpointIntegrity, AByteFlippedInAnyDatasetIsRefusedNamingIt) {
    const CheckpointedSpray spray("checkpoint-damage");
    ASSERT_EQ(spray.status, 0) << slurp(spray.path / "log");
    const fs::path pristine = spray.path / "pristine.h5";
    fs::copy_file(spray.checkpoint(), pristine);
    const auto datasets = datasetsWithData(pristine);
    // The cloud's arrays, the arrivals, counters by exit and surface, the frame list.
    ASSERT_GE(datasets.size(), 10u);
    for (const std::string& dataset : datasets) {
        fs::copy_file(pristine, spray.checkpoint(), fs::copy_options::overwrite_existing);
        flipByteIn(spray.checkpoint(), dataset);
        const fs::path log = spray.path / "restart.log";
        EXPECT_EQ(runCli(spray.path.string() + " --quiet --restart --end-time 0.005", log), 2)
            << dataset << ": " << slurp(log);
        const std::string message = slurp(log);
        EXPECT_NE(message.find(spray.checkpoint().string() + ": cannot read dataset " + dataset +
                               " (damaged"),
                  std::string::npos)
            << message;
    }
}

// The frames before the checkpoint are written to particles.h5 again from their .vtp files: one
// that cannot be read (zlib's Adler-32 finds the changed byte) is refused by name.
TEST(CheckpointIntegrity, ADamagedFrameFileIsRefusedNamingIt) {
    const CheckpointedSpray spray("checkpoint-frame-damage");
    ASSERT_EQ(spray.status, 0) << slurp(spray.path / "log");
    const fs::path frame = spray.output() / "particles_000005.vtp";
    std::string bytes = slurp(frame);
    bytes[bytes.size() * 2 / 3] ^= 0x5a; // inside the appended, compressed arrays
    std::ofstream(frame, std::ios::binary) << bytes;
    const fs::path log = spray.path / "restart.log";
    EXPECT_EQ(runCli(spray.path.string() + " --quiet --restart --end-time 0.005", log), 2);
    EXPECT_TRUE(slurp(log).ends_with("\nslides-track: error: " + frame.string() +
                                     ": damaged frame: VTK cannot read it\n"))
        << slurp(log);
}

TEST(CheckpointIntegrity, SizeDoesNotGrowWithTheFrames) {
    // The same 400 steps with 9 frames (every 0.5 ms from 0) and with 81.
    const CheckpointedSpray few("checkpoint-few-frames", "5e-4");
    const CheckpointedSpray many("checkpoint-many-frames", "5e-5");
    ASSERT_EQ(few.status, 0) << slurp(few.path / "log");
    ASSERT_EQ(many.status, 0) << slurp(many.path / "log");
    const auto fewBytes = static_cast<double>(fs::file_size(few.checkpoint()));
    const auto manyBytes = static_cast<double>(fs::file_size(many.checkpoint()));
    // 72 more frame records of 16 bytes each: within 4 KiB; a copy of the frames (up to 3200
    // particles each) would add megabytes.
    EXPECT_NEAR(manyBytes, fewBytes, 4096);
}

TEST(CheckpointIntegrity, RestartRemovesTheTemporariesOfDeadRuns) {
    const CheckpointedSpray spray("checkpoint-temporaries");
    ASSERT_EQ(spray.status, 0) << slurp(spray.path / "log");
    // A process id that is free: a child that has exited and been reaped.
    const pid_t child = ::fork();
    if (child == 0) ::_exit(0);
    ASSERT_GT(child, 0);
    ::waitpid(child, nullptr, 0);
    const std::string dead = ".tmp-" + std::to_string(child);
    const std::string alive = ".tmp-" + std::to_string(::getpid()); // this test, running
    for (const std::string& name : {"checkpoint.h5" + dead, "particles_000001.vtp" + dead,
                                    "particles.h5.partial" + dead, "summary.json" + alive})
        std::ofstream(spray.output() / name) << "left by a killed run";
    ASSERT_EQ(runCli(spray.path.string() + " --quiet --restart --end-time 0.0041",
                     spray.path / "restart.log"),
              0)
        << slurp(spray.path / "restart.log");
    EXPECT_FALSE(fs::exists(spray.output() / ("checkpoint.h5" + dead)));
    EXPECT_FALSE(fs::exists(spray.output() / ("particles_000001.vtp" + dead)));
    EXPECT_FALSE(fs::exists(spray.output() / ("particles.h5.partial" + dead)));
    EXPECT_TRUE(fs::exists(spray.output() / ("summary.json" + alive)))
        << "the temporary of a running process was removed";
}

TEST(CheckpointIntegrity, SummaryAfterRestartReportsTheWholeRun) {
    const CheckpointedSpray spray("checkpoint-summary");
    ASSERT_EQ(spray.status, 0) << slurp(spray.path / "log");
    const auto first = nlohmann::json::parse(slurp(spray.output() / "summary.json"));
    double checkpointedStepping = 0;
    {
        const Hdf5File checkpoint(spray.checkpoint(), Hdf5Access::readOnly);
        checkpointedStepping = checkpoint.readDouble("/checkpoint", "steppingSeconds");
    }
    // The checkpoint was written after the last step: it holds the first segment's stepping.
    EXPECT_EQ(checkpointedStepping, first["performance"]["steppingSeconds"].get<double>());
    // One more step.
    ASSERT_EQ(runCli(spray.path.string() + " --quiet --restart --end-time 0.00401",
                     spray.path / "restart.log"),
              0)
        << slurp(spray.path / "restart.log");
    const auto whole = nlohmann::json::parse(slurp(spray.output() / "summary.json"));
    const auto& performance = whole["performance"];
    const double stepping = performance["steppingSeconds"].get<double>();
    const auto particleSteps = performance["particleSteps"].get<std::uint64_t>();
    EXPECT_GT(particleSteps, first["performance"]["particleSteps"].get<std::uint64_t>());
    EXPECT_GT(stepping, checkpointedStepping); // both segments, not the last one's step alone
    EXPECT_GE(performance["wallSeconds"].get<double>(), stepping);
    EXPECT_NEAR(performance["particleStepsPerSecond"].get<double>(),
                static_cast<double>(particleSteps) / stepping,
                1e-12 * static_cast<double>(particleSteps) / stepping);
}

} // namespace
} // namespace slides
