// ctest-labels: robustness io
// Writes that fail: a checkpoint whose final flush meets the end of the space (injected as a
// file-size limit, which works for any user: writes beyond it fail with EFBIG), and a file whose
// temporary cannot be created (a name too long for it, which no user can create either). Each
// ends in one message naming the file, and what was written before stays whole.
#include "../support/case_runs.h"
#include "slides/io/atomic_file.h"
#include "slides/io/hdf5_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace slides {
namespace {

namespace fs = std::filesystem;

/// The analytic spray with 500 particles, a small carrier lattice and `output`: its checkpoints
/// grow from 30 kB (step 50) to 41 kB, the carrier file is 5.5 kB, frames of ids alone stay
/// below 17 kB, and particles.h5 grows past 300 kB.
struct SmallSpray : test::ScratchDirectory {
    explicit SmallSpray(const std::string& output = "hdf5 no; fields (id);")
        : test::ScratchDirectory("output-faults") {
        std::ofstream(path / "constant" / "slidesProperties")
            << "#include \"" << (test::defaultCase / "constant" / "slidesProperties").string()
            << "\"\nparticles { count 500; }\noutput { carrierResolution (8 8 8); " << output
            << " }\n";
    }
};

/// Runs spray with checkpoints every 50 steps under a file-size limit of `kib` KiB (writes past
/// it fail with EFBIG): the run must end with exit status 2; returns its last error line.
std::string lastErrorUnderFileSizeLimit(const SmallSpray& spray, int kib) {
    const fs::path log = spray.path / "log";
    const std::string command = "/bin/bash -c \"trap '' XFSZ; ulimit -f " + std::to_string(kib) +
                                "; exec " + std::string(SLIDES_TRACK_EXE) + " " +
                                spray.path.string() + " --output " + (spray.path / "out").string() +
                                " --checkpoint-every 50 --threads 1\" > " + log.string() + " 2>&1";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status)) << "killed by signal " << WTERMSIG(status);
    EXPECT_EQ(WEXITSTATUS(status), 2);
    const std::string text = test::slurp(log);
    return text.substr(text.rfind("\nslides-track: error: ") + 1);
}

// The checkpoint after the first one cannot be closed (HDF5 flushes it on closing, past the
// 33 KiB limit): the run printed its error and then died of SIGSEGV in HDF5's shutdown, which
// closed the half-closed file a second time.
TEST(OutputFaults, CheckpointThatCannotBeFlushedEndsInExitTwoKeepingThePreviousOne) {
    const SmallSpray spray;
    const fs::path out = spray.path / "out";
    const std::string error = lastErrorUnderFileSizeLimit(spray, 33);
    EXPECT_TRUE(error.starts_with("slides-track: error: cannot write " +
                                  (out / "checkpoint.h5.tmp-").string()))
        << error;
    EXPECT_TRUE(error.ends_with(": cannot close the file (File too large)\n")) << error;
    for (const auto& entry : fs::directory_iterator(out))
        EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
            << entry.path();
    // The previous checkpoint is whole: the run restarts from it and ends.
    EXPECT_EQ(
        test::runCli(spray.path.string() + " --output " + out.string() + " --restart --threads 1",
                     spray.path / "restart.log"),
        0)
        << test::slurp(spray.path / "restart.log");
    EXPECT_TRUE(fs::exists(out / "summary.json"));
}

// particles.h5.partial cannot be flushed past the 350 KiB limit: HDF5 may leave it unreadable
// (its /frames group half written), so a restart writes the frames before the checkpoint anew
// from their .vtp files, and ends with every frame in particles.h5.
TEST(OutputFaults, FramesThatCannotBeFlushedAreWrittenAgainOnRestart) {
    const SmallSpray spray("");
    const fs::path out = spray.path / "out";
    const std::string error = lastErrorUnderFileSizeLimit(spray, 350);
    EXPECT_EQ(error, "slides-track: error: cannot write " +
                         (out / "particles.h5.partial").string() +
                         ": cannot flush to disk (File too large)\n");
    EXPECT_EQ(
        test::runCli(spray.path.string() + " --output " + out.string() + " --restart --threads 1",
                     spray.path / "restart.log"),
        0)
        << test::slurp(spray.path / "restart.log");
    std::size_t frames = 0;
    for (const auto& entry : fs::directory_iterator(out))
        frames += entry.path().extension() == ".vtp" &&
                  entry.path().filename().string().starts_with("particles_");
    const Hdf5File particles(out / "particles.h5", Hdf5Access::readOnly);
    EXPECT_EQ(particles.readInt64("/", "frames"), static_cast<std::int64_t>(frames));
    for (std::size_t n = 0; n < frames; ++n) {
        char group[32];
        std::snprintf(group, sizeof group, "/frames/%06zu", n);
        EXPECT_NO_THROW(particles.readDoubles(std::string(group) + "/position", 3)) << group;
    }
}

// A full disk, on tmpfs file systems of 100 kB to 800 kB (mounting needs root): wherever the
// space ends (the carrier, a frame, the series, particles.h5.partial, a checkpoint), the message
// names the file and the system's reason; copying the frames into the checkpoint said
// `Input/output error`, and a failed flush of particles.h5.partial gave no reason.
TEST(OutputFaults, FullDiskNamesTheFileAndNoSpace) {
    const SmallSpray spray("");
    const fs::path disk = spray.path / "disk";
    fs::create_directories(disk);
    for (const char* size : {"100k", "200k", "300k", "400k", "800k"}) {
        const std::string mount = "mount -t tmpfs -o size=" + std::string(size) + " tmpfs " +
                                  disk.string() + " 2> /dev/null";
        if (std::system(mount.c_str()) != 0) GTEST_SKIP() << "cannot mount a tmpfs (not root)";
        const fs::path log = spray.path / "log";
        const int status =
            test::runCli(spray.path.string() + " --output " + (disk / "out").string() +
                             " --checkpoint-every 50 --threads 1 --quiet",
                         log);
        const std::string text = test::slurp(log);
        EXPECT_EQ(status, 2) << size << ": " << text;
        EXPECT_NE(text.find("slides-track: error: cannot write " + (disk / "out").string() + "/"),
                  std::string::npos)
            << size << ": " << text;
        EXPECT_TRUE(text.ends_with("(No space left on device)\n") ||
                    text.ends_with(": No space left on device\n"))
            << size << ": " << text;
        ASSERT_EQ(std::system(("umount " + disk.string()).c_str()), 0);
    }
}

// The temporary's name (target + ".tmp-PID") is longer than a file name may be: even root cannot
// create it. The message names the target with the system's reason; the target keeps its text.
TEST(OutputFaults, UncreatableTemporaryKeepsTheOriginal) {
    const test::ScratchDirectory directory("uncreatable-temporary");
    const fs::path target = directory.path / (std::string(250, 'p') + ".pvd");
    std::ofstream(target) << "original";
    try {
        writeTextAtomically(target, "new");
        ADD_FAILURE() << "no OutputError";
    } catch (const OutputError& error) {
        EXPECT_EQ(std::string(error.what()),
                  "cannot write " + target.string() + ": File name too long");
    }
    EXPECT_EQ(test::slurp(target), "original");
}

} // namespace
} // namespace slides
