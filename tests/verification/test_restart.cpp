// ctest-labels: restart io
// Checkpoint and restart (io/checkpoint.h) through the command line: a run killed with SIGKILL
// in the middle (checkpoints every few steps, so the kill often lands inside a write) restarts
// from its last checkpoint and ends with files identical byte for byte to an uninterrupted
// run's (frames, series, HDF5 data, summary apart from its timings), at another thread count,
// also in the pulsed jet (an unsteady carrier, carrier/pulsed_jet.h);
// a damaged, truncated or mismatched checkpoint (other dictionary, time step or version) is
// refused with exit status 2 and a message naming it, and the existing output is left alone.
#include "../support/case_runs.h"
#include "slides/io/hdf5_file.h"

#include <gtest/gtest.h>
#include <hdf5.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <thread>
#include <vector>

namespace slides {
namespace {

namespace fs = std::filesystem;
using test::defaultCase;
using test::runCli;
using test::ScratchDirectory;
using test::slurp;

/// Physics beyond the default case's drag and gravity, each with per-particle state that a
/// checkpoint must carry.
enum class ExtraPhysics {
    none,
    unsteadyForces,       ///< history memory, spin and the rest of the Maxey–Riley state
    finiteReynolds,       ///< Kim's history memory (per-interval crossovers, infinite at no slip)
    dispersionAndHeat,    ///< eddy states with their random-event counters, temperatures
    collisionsAndDeposit, ///< spins, the deposit (rebuilt from the arrivals), contact counts
    softSpheres,          ///< contact loads and the springs of touching contacts
    electromagnetic,      ///< the particles' charges (Lorentz force, Eq. 2.93)
    pulsedJet, ///< an unsteady carrier (carrier/pulsed_jet.h): ∂U/∂t, the run's time in the gas
};

/// Inserts entry after the first occurrence of anchor in text.
void insertAfter(std::string& text, const std::string& anchor, const std::string& entry) {
    const auto at = text.find(anchor);
    ASSERT_NE(at, std::string::npos) << anchor;
    text.insert(at + anchor.size(), entry);
}

/// The default case copied into scratch (so tests may edit it), with the extra physics on.
void copyDefaultCase(const ScratchDirectory& scratch, ExtraPhysics physics = ExtraPhysics::none) {
    std::string text = slurp(defaultCase / "constant" / "slidesProperties");
    if (physics == ExtraPhysics::unsteadyForces)
        insertAfter(text, "buoyancy    on;",
                    " history { model basset; } addedMass on; pressureGradient on;"
                    " lift saffmanMeiMagnus; spin on;");
    if (physics == ExtraPhysics::finiteReynolds)
        insertAfter(text, "buoyancy    on;", " history { model kim; }");
    if (physics == ExtraPhysics::dispersionAndHeat) {
        insertAfter(text, "buoyancy    on;",
                    " dispersion { model eddyInteraction; } heatTransfer { model ranzMarshall; }");
        insertAfter(text, "        effectiveViscosity 1.4e-3;\n    }\n",
                    "    turbulence { scaling jetLocal; intensity 0.25; lengthScaleToHalfWidth "
                    "0.2; }\n");
        insertAfter(text, "    density     5680;\n",
                    "    specificHeat 460;\n    injectionTemperature 600;\n");
    }
    if (physics == ExtraPhysics::collisionsAndDeposit) {
        insertAfter(text, "        normal  (-1 0 0);\n", "        interaction deposit;\n");
        insertAfter(
            text,
            "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n",
            "collisions { model impulse; }\ndeposition { adhesionFactor 5000; }\n");
        // Most of the deposit forms by 15 ms; a few particles would bounce on to 0.1 s.
        const auto end = text.find("endTime         0.1;");
        ASSERT_NE(end, std::string::npos);
        text.replace(end, 20, "endTime         0.015;");
    }
    if (physics == ExtraPhysics::softSpheres) {
        // Soft particles (E* ≈ 1.3e5 Pa), so that the given step resolves their contacts (about
        // ten steps at 1 m/s, Eq. 2.59); the target becomes a soft wall.
        insertAfter(text, "        normal  (-1 0 0);\n", "        interaction rebound;\n");
        const auto moduli =
            text.find("        bulkModulus     167e9;\n        shearModulus    77e9;");
        ASSERT_NE(moduli, std::string::npos);
        text.replace(moduli, 60, "        bulkModulus     1e5;\n        shearModulus    5e4;");
        insertAfter(
            text,
            "// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //\n",
            "collisions { model softSphere; restitution { model constant; coefficient 0.8; } }\n");
        const auto end = text.find("endTime         0.1;");
        ASSERT_NE(end, std::string::npos);
        text.replace(end, 20, "endTime         0.015;");
    }
    if (physics == ExtraPhysics::electromagnetic) {
        insertAfter(text, "buoyancy    on;",
                    " electromagnetic { model lorentz; E (0 -2e5 0); B (0 0 0.1);"
                    " charge { model surface; value 2e-5; } }");
        const auto end = text.find("endTime         0.1;");
        ASSERT_NE(end, std::string::npos);
        text.replace(end, 20, "endTime         0.015;");
    }
    if (physics == ExtraPhysics::pulsedJet) {
        insertAfter(text, "        effectiveViscosity 1.4e-3;\n",
                    "        pulsation { amplitude 0.3; frequency 200; }\n");
        insertAfter(text, "buoyancy    on;", " addedMass on; pressureGradient on;");
    }
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
}

std::vector<std::string> frameFiles(const fs::path& directory) {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory))
        if (entry.path().extension() == ".vtp" &&
            entry.path().filename().string().starts_with("particles_"))
            names.push_back(entry.path().filename());
    std::sort(names.begin(), names.end());
    return names;
}

/// summary.json without what depends on the machine's speed.
nlohmann::json resultsOf(const fs::path& directory) {
    auto summary = nlohmann::json::parse(slurp(directory / "summary.json"));
    summary.erase("performance");
    return summary;
}

/// Starts slides-track with arguments and kills it (SIGKILL) `delay` after its first
/// checkpoint appears; returns whether it was still running then.
bool killMidRun(const std::vector<std::string>& arguments, const fs::path& checkpoint,
                std::chrono::milliseconds delay) {
    const pid_t child = ::fork();
    if (child == 0) {
        std::vector<char*> argv{const_cast<char*>(SLIDES_TRACK_EXE)};
        for (const auto& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
        argv.push_back(nullptr);
        ::execv(SLIDES_TRACK_EXE, argv.data());
        ::_exit(127);
    }
    int status = 0;
    while (!fs::exists(checkpoint) && ::waitpid(child, &status, WNOHANG) == 0)
        std::this_thread::sleep_for(std::chrono::milliseconds(2));
    std::this_thread::sleep_for(delay);
    ::kill(child, SIGKILL);
    ::waitpid(child, &status, 0);
    return WIFSIGNALED(status);
}

struct KillMoment {
    int delayMilliseconds; ///< after the first checkpoint appears
    ExtraPhysics physics;
};

class KilledRun : public testing::TestWithParam<KillMoment> {};

TEST_P(KilledRun, RestartsFromTheLastCheckpointToIdenticalFiles) {
    const auto [delay, physics] = GetParam();
    ScratchDirectory scratch("restart-" + std::to_string(delay) + "-" +
                             std::to_string(static_cast<int>(physics)));
    copyDefaultCase(scratch, physics);
    const fs::path reference = scratch.path / "reference";
    const fs::path resumed = scratch.path / "resumed";
    ASSERT_EQ(runCli(scratch.path.string() + " --quiet --threads 2 --output " + reference.string(),
                     scratch.path / "reference.log"),
              0);

    const bool killed = killMidRun({scratch.path.string(), "--quiet", "--threads", "2",
                                    "--checkpoint-every", "20", "--output", resumed.string()},
                                   resumed / "checkpoint.h5", std::chrono::milliseconds(delay));
    ASSERT_TRUE(killed) << "the run ended before it could be killed: the test proves nothing";
    ASSERT_FALSE(fs::exists(resumed / "summary.json"));
    // What the killed run completed is intact: no temporaries pass for files.
    const auto before = frameFiles(resumed);
    ASSERT_FALSE(before.empty());

    ASSERT_EQ(runCli(scratch.path.string() + " --quiet --restart --threads 1 --output " +
                         resumed.string(),
                     scratch.path / "resumed.log"),
              0)
        << slurp(scratch.path / "resumed.log");
    const auto frames = frameFiles(reference);
    ASSERT_EQ(frameFiles(resumed), frames);
    for (const auto& frame : frames)
        EXPECT_EQ(slurp(resumed / frame), slurp(reference / frame)) << frame;
    EXPECT_EQ(slurp(resumed / "particles.pvd"), slurp(reference / "particles.pvd"));
    EXPECT_EQ(slurp(resumed / "particles.xmf"), slurp(reference / "particles.xmf"));
    for (const char* deposit : {"deposit.vtp", "deposit_target.vti"})
        EXPECT_EQ(fs::exists(reference / deposit) ? slurp(resumed / deposit) : "",
                  fs::exists(reference / deposit) ? slurp(reference / deposit) : "")
            << deposit;
    EXPECT_EQ(resultsOf(resumed), resultsOf(reference));
    EXPECT_FALSE(fs::exists(resumed / "particles.h5.partial"));

    // The HDF5 data: every frame's positions and the arrivals, value for value.
    const Hdf5File expected(reference / "particles.h5", Hdf5Access::readOnly);
    const Hdf5File actual(resumed / "particles.h5", Hdf5Access::readOnly);
    EXPECT_FALSE(actual.exists("/checkpoint"));
    ASSERT_EQ(actual.readInt64("/", "frames"), expected.readInt64("/", "frames"));
    for (std::size_t n = 0; n < frames.size(); ++n) {
        char group[32];
        std::snprintf(group, sizeof group, "/frames/%06zu", n);
        EXPECT_EQ(actual.readDouble(group, "time"), expected.readDouble(group, "time"));
        EXPECT_EQ(actual.readDoubles(std::string(group) + "/position", 3),
                  expected.readDoubles(std::string(group) + "/position", 3))
            << group;
    }
    EXPECT_EQ(actual.readUInt64("/arrivals/id"), expected.readUInt64("/arrivals/id"));
    EXPECT_EQ(actual.readDoubles("/arrivals/velocity", 3),
              expected.readDoubles("/arrivals/velocity", 3));
}

std::string killMomentName(const testing::TestParamInfo<KillMoment>& info) {
    const char* physics[] = {"",
                             "WithUnsteadyForces",
                             "WithFiniteReynoldsHistory",
                             "WithDispersionAndHeat",
                             "WithCollisionsAndDeposit",
                             "WithSoftSpheres",
                             "WithElectromagneticForces",
                             "InAPulsedJet"};
    return std::to_string(info.param.delayMilliseconds) + "ms" +
           physics[static_cast<int>(info.param.physics)];
}

// Kill moments after the first checkpoint: soon, and well into the run; and with the model
// states of the unsteady forces, and of dispersion and heating, to carry across; and in an
// unsteady carrier, whose gas depends on the run's time.
INSTANTIATE_TEST_SUITE_P(Moments, KilledRun,
                         testing::Values(KillMoment{0, ExtraPhysics::none},
                                         KillMoment{150, ExtraPhysics::none},
                                         KillMoment{100, ExtraPhysics::unsteadyForces},
                                         KillMoment{100, ExtraPhysics::finiteReynolds},
                                         KillMoment{100, ExtraPhysics::dispersionAndHeat},
                                         KillMoment{100, ExtraPhysics::collisionsAndDeposit},
                                         KillMoment{100, ExtraPhysics::softSpheres},
                                         KillMoment{100, ExtraPhysics::electromagnetic},
                                         KillMoment{100, ExtraPhysics::pulsedJet}),
                         killMomentName);

/// A short run of the default case (copied to scratch) that leaves a checkpoint.
class Checkpointed : public testing::Test {
protected:
    Checkpointed() : scratch_("checkpointed") {}
    void SetUp() override {
        copyDefaultCase(scratch_);
        ASSERT_EQ(runCli(caseArgument() + " --quiet --end-time 0.002 --checkpoint-every 100",
                         scratch_.path / "log"),
                  0);
        ASSERT_TRUE(fs::exists(checkpoint()));
        frames_ = frameFiles(output());
    }
    std::string caseArgument() const { return scratch_.path.string(); }
    fs::path output() const { return scratch_.path / "slides"; }
    fs::path checkpoint() const { return output() / "checkpoint.h5"; }

    /// Restarts, expecting the refusal: exit status 2, one message naming the checkpoint
    /// and containing `reason`, and the output of the earlier run untouched.
    void expectRefused(const std::string& arguments, const std::string& reason) {
        const auto log = scratch_.path / "restart.log";
        EXPECT_EQ(runCli(caseArgument() + " --quiet --restart " + arguments, log), 2);
        const std::string message = slurp(log);
        EXPECT_NE(message.find(checkpoint().string()), std::string::npos) << message;
        EXPECT_NE(message.find(reason), std::string::npos) << message;
        EXPECT_EQ(frameFiles(output()), frames_);
        EXPECT_TRUE(fs::exists(output() / "particles.h5"));
    }

    ScratchDirectory scratch_;
    std::vector<std::string> frames_;
};

TEST_F(Checkpointed, RestartOfTheSameRunSucceeds) {
    // The control for the refusals below: the same case and options restart cleanly.
    EXPECT_EQ(runCli(caseArgument() + " --quiet --restart --end-time 0.002", scratch_.path / "l"),
              0)
        << slurp(scratch_.path / "l");
}

TEST_F(Checkpointed, TruncatedCheckpointIsRefused) {
    fs::resize_file(checkpoint(), fs::file_size(checkpoint()) / 2);
    expectRefused("--end-time 0.002", "not a readable HDF5 file");
}

TEST_F(Checkpointed, FlippedByteInTheParticleDataIsRefused) {
    // Flip one byte in the middle of the stored particle positions' data chunk: the
    // Fletcher-32 checksum (or the deflate stream) must catch it.
    haddr_t address = 0;
    hsize_t size = 0;
    {
        const hid_t file = H5Fopen(checkpoint().c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
        const hid_t dataset = H5Dopen2(file, "/checkpoint/cloud/position", H5P_DEFAULT);
        const hid_t space = H5Dget_space(dataset);
        ASSERT_GE(H5Dget_chunk_info(dataset, space, 0, nullptr, nullptr, &address, &size), 0);
        H5Sclose(space);
        H5Dclose(dataset);
        H5Fclose(file);
    }
    ASSERT_GT(size, 0u);
    std::fstream file(checkpoint(), std::ios::in | std::ios::out | std::ios::binary);
    file.seekg(static_cast<std::streamoff>(address + size / 2));
    const char byte = static_cast<char>(file.get());
    file.seekp(static_cast<std::streamoff>(address + size / 2));
    file.put(static_cast<char>(byte ^ 0x5a));
    file.close();
    expectRefused("--end-time 0.002", "damaged");
}

TEST_F(Checkpointed, OtherTimeStepIsRefused) {
    expectRefused("--end-time 0.002 --dt 2e-5",
                  "written with dt = 1e-05 s, this run has dt = 2e-05 s");
}

TEST_F(Checkpointed, EditedDictionaryIsRefused) {
    std::string text = slurp(scratch_.path / "constant" / "slidesProperties");
    const auto at = text.find("seed");
    ASSERT_NE(at, std::string::npos);
    text.insert(at, "// edited\n    ");
    std::ofstream(scratch_.path / "constant" / "slidesProperties") << text;
    expectRefused("--end-time 0.002", "written for another case dictionary");
}

TEST_F(Checkpointed, OtherVersionIsRefused) {
    {
        Hdf5File edited(checkpoint(), Hdf5Access::readWrite);
        const Hdf5Handle group(H5Gopen2(edited.root(), "/checkpoint", H5P_DEFAULT));
        ASSERT_GE(H5Adelete(group.get(), "version"), 0);
        edited.writeAttribute(group.get(), "version", "0.0.0");
    }
    expectRefused("--end-time 0.002", "written by SLIDES-track 0.0.0");
}

TEST_F(Checkpointed, MissingCheckpointIsRefused) {
    fs::remove(checkpoint());
    expectRefused("--end-time 0.002", "no checkpoint here");
}

} // namespace
} // namespace slides
