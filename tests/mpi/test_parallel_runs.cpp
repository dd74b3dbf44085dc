// ctest-labels: foam
// foam-cases: impingingJet3d impingingJet mpiCases
// `mpirun -np N slides-track CASE -parallel` on decomposed copies of the solved 3-D impinging jet
// (tools/decompose-foam-cases; 19 680 cells, 2000 particles of 20 µm with eddy-interaction
// dispersion, cell interpolation, no term that needs ∇U). Particle conservation: injected =
// arrived + escaped (by patch, never a processor patch) + moving, on every rank count. The
// arrivals, sorted by id, are those of the serial run bit for bit: a particle's draws are keyed
// by its id (DESIGN.md), the parts' cell values are the whole case's, and a particle crossing a
// processor patch goes on from the matching face in the same step (run/rank_exchange.h). Each
// refused input ends every rank with exit status 2, one message, and nothing written. On the
// axisymmetric 5° wedge of the same jet, each part finds the wedge's axis from its own faces of
// the wedge patches, so the arrivals agree with the serial run's to round-off. A checkpoint of
// one rank count restarts on another, or serially, to the serial run's arrivals bit for bit.
#include "../support/case_runs.h"

#include "slides/io/hdf5_file.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numeric>
#include <string>

namespace {

namespace fs = std::filesystem;

const fs::path cases = SLIDES_MPI_CASES_DIR;
using slides::test::slurp;

/// The run's output directory, fresh for each test.
fs::path scratch(const std::string& name) {
    const fs::path dir =
        fs::temp_directory_path() / ("slides-mpi-" + name + "-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

/// `slides-track CASE` (ranks 0: serial; else under mpirun with that many ranks, -parallel),
/// one thread a rank, output to output; the exit status, the console in output.log.
int track(const std::string& caseName, int ranks, const fs::path& output,
          const std::string& extra = "") {
    std::string command = "OMP_NUM_THREADS=1 ";
    if (ranks > 0)
        // As root (CI), oversubscribed (2 cores here); OpenMPI's own allocations are not leaks
        // of ours: leak checks off for these runs under AddressSanitizer (tools/sanitize).
        command += "ASAN_OPTIONS=\"${ASAN_OPTIONS}:detect_leaks=0\" mpirun --allow-run-as-root "
                   "--oversubscribe --mca btl_vader_single_copy_mechanism none -np " +
                   std::to_string(ranks) + " ";
    command += std::string(SLIDES_TRACK_EXE) + " " + (cases / caseName).string() +
               (ranks > 0 ? " -parallel" : "") + " --threads 1 --quiet --output " +
               output.string() + " " + extra + " > " + output.string() + ".log 2>&1";
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Arrivals {
    std::vector<std::uint64_t> id;
    std::vector<double> time, position, velocity;
};

/// particles.h5's arrivals, sorted by id.
Arrivals arrivalsOf(const fs::path& output) {
    const slides::Hdf5File file(output / "particles.h5", slides::Hdf5Access::readOnly);
    const auto id = file.readUInt64("/arrivals/id");
    const auto time = file.readDoubles("/arrivals/time", 1);
    const auto position = file.readDoubles("/arrivals/position", 3);
    const auto velocity = file.readDoubles("/arrivals/velocity", 3);
    std::vector<std::size_t> order(id.size());
    std::iota(order.begin(), order.end(), std::size_t{0});
    std::sort(order.begin(), order.end(), [&](auto a, auto b) { return id[a] < id[b]; });
    Arrivals sorted;
    for (const std::size_t k : order) {
        sorted.id.push_back(id[k]);
        sorted.time.push_back(time[k]);
        for (int d = 0; d < 3; ++d) {
            sorted.position.push_back(position[3 * k + d]);
            sorted.velocity.push_back(velocity[3 * k + d]);
        }
    }
    return sorted;
}

nlohmann::json summaryOf(const fs::path& output) {
    return nlohmann::json::parse(slurp(output / "summary.json"));
}

/// injected = arrived + escaped + moving, and no processor patch among the exits.
void expectConserved(const nlohmann::json& particles) {
    long arrived = 0, escaped = 0;
    for (const auto& [surface, count] : particles["arrived"].items()) arrived += count.get<long>();
    for (const auto& [exit, count] : particles["escapedThrough"].items()) {
        EXPECT_EQ(exit.find("procBoundary"), std::string::npos) << exit;
        escaped += count.get<long>();
    }
    EXPECT_EQ(escaped, particles["escaped"].get<long>());
    EXPECT_EQ(particles["injected"].get<long>(), 2000);
    EXPECT_EQ(particles["injected"].get<long>(),
              arrived + escaped + particles["active"].get<long>());
}

/// The serial run of the same case (its whole mesh and solution beside the parts).
const fs::path& serialRun() {
    static const fs::path output = [] {
        const fs::path dir = scratch("serial");
        EXPECT_EQ(track("x2", 0, dir), 0) << slurp(dir.string() + ".log");
        return dir;
    }();
    return output;
}

void expectAsSerial(const fs::path& output) {
    const Arrivals serial = arrivalsOf(serialRun()), parallel = arrivalsOf(output);
    EXPECT_EQ(parallel.id, serial.id);
    EXPECT_EQ(parallel.time, serial.time);
    EXPECT_EQ(parallel.position, serial.position);
    EXPECT_EQ(parallel.velocity, serial.velocity);
    EXPECT_EQ(summaryOf(output)["particles"], summaryOf(serialRun())["particles"]);
}

class ParallelRun : public ::testing::TestWithParam<int> {};

TEST_P(ParallelRun, ConservesParticlesAndMatchesTheSerialRunBitForBit) {
    const int ranks = GetParam();
    std::string slabs(1, 'x'); // the case decomposed into `ranks` slabs
    slabs += std::to_string(ranks);
    const fs::path output = scratch(slabs);
    ASSERT_EQ(track(slabs, ranks, output), 0) << slurp(output.string() + ".log");
    const auto summary = summaryOf(output);
    expectConserved(summary["particles"]);
    ASSERT_EQ(summary["performance"]["ranks"].size(), static_cast<std::size_t>(ranks));
    expectAsSerial(output);
    fs::remove_all(output);
}

INSTANTIATE_TEST_SUITE_P(SlabsAcrossTheJet, ParallelRun, ::testing::Values(1, 2, 3, 4));

/// The largest |a − b| over two equally long lists.
double largestDifference(const std::vector<double>& a, const std::vector<double>& b) {
    double largest = 0;
    for (std::size_t k = 0; k < a.size() && k < b.size(); ++k)
        largest = std::max(largest, std::abs(a[k] - b[k]));
    return largest;
}

TEST(ParallelRuns, OnAWedgeMeshAgreeWithTheSerialRunToRoundOff) {
    const fs::path serial = scratch("wedgeSerial");
    ASSERT_EQ(track("wedgeX2", 0, serial), 0) << slurp(serial.string() + ".log");
    const Arrivals reference = arrivalsOf(serial);
    ASSERT_GT(reference.id.size(), 1000u) << "most particles reach the plate";
    for (const char* parts : {"wedgeX2", "wedgeRandom2"}) {
        const fs::path output = scratch(parts);
        ASSERT_EQ(track(parts, 2, output), 0) << slurp(output.string() + ".log");
        const auto summary = summaryOf(output);
        expectConserved(summary["particles"]);
        EXPECT_EQ(summary["particles"], summaryOf(serial)["particles"]) << parts;
        const Arrivals arrivals = arrivalsOf(output);
        ASSERT_EQ(arrivals.id, reference.id) << parts;
        // The parts' axes differ from the whole mesh's in the last bits (1e-16 of 0.04 m).
        EXPECT_LT(largestDifference(arrivals.position, reference.position), 1e-12) << parts;
        EXPECT_LT(largestDifference(arrivals.velocity, reference.velocity), 1e-9) << parts;
        EXPECT_LT(largestDifference(arrivals.time, reference.time), 1e-12) << parts;
        fs::remove_all(output);
    }
    fs::remove_all(serial);
}

TEST(ParallelRuns, RandomDecompositionCrossesProcessorPatchesManyTimesAndLosesNothing) {
    // Every cell in a random one of 4 parts: a particle crosses a processor patch at almost
    // every cell face it passes, several per step (multi-hop rounds).
    const fs::path output = scratch("random4");
    ASSERT_EQ(track("random4", 4, output), 0) << slurp(output.string() + ".log");
    const auto summary = summaryOf(output);
    expectConserved(summary["particles"]);
    double crossings = 0;
    for (const auto& rank : summary["performance"]["ranks"])
        crossings += rank["particlesSent"].get<double>();
    EXPECT_GT(crossings, 10 * 2000); // measured 63 338: 32 crossings a particle
    expectAsSerial(output);
    fs::remove_all(output);
}

TEST(ParallelRuns, BinaryPartsAcrossTheJetAgreeWithTheSerialRun) {
    // decomposePar in binary, 4 slabs across y: counts as in serial; the arrivals to round-off
    // (cells whose faces the parts list in another order sum their centres in another order).
    const fs::path output = scratch("y4binary");
    ASSERT_EQ(track("y4binary", 4, output), 0) << slurp(output.string() + ".log");
    EXPECT_EQ(summaryOf(output)["particles"], summaryOf(serialRun())["particles"]);
    const Arrivals serial = arrivalsOf(serialRun()), parallel = arrivalsOf(output);
    ASSERT_EQ(parallel.id, serial.id);
    for (std::size_t k = 0; k < serial.velocity.size(); ++k) // |v| ≈ 25 m/s
        EXPECT_NEAR(parallel.velocity[k], serial.velocity[k], 1e-9);
    fs::remove_all(output);
}

TEST(ParallelRuns, CellPointValuesAtProcessorPatchesAreTheWholeMeshs) {
    // cellPoint point values at processor-patch points are fitted over every part's cells and
    // faces (carrier/foam_shared_points.h). Each part's own cells alone gave a random 4-part
    // decomposition other velocity gradients, and its scene analysis turned lift and spin on.
    // Agreement to round-off, not bits: measured 4e-14 m/s in the arrival velocities (~25 m/s),
    // 4e-17 m in the positions, from cell centres summed over their faces in another order.
    const fs::path serial = scratch("cellPointSerial"), output = scratch("cellPoint4");
    ASSERT_EQ(track("random4cellPoint", 0, serial), 0) << slurp(serial.string() + ".log");
    ASSERT_EQ(track("random4cellPoint", 4, output), 0) << slurp(output.string() + ".log");
    EXPECT_EQ(summaryOf(output)["particles"], summaryOf(serial)["particles"]);
    EXPECT_EQ(summaryOf(output)["settings"]["physics"], summaryOf(serial)["settings"]["physics"]);
    const Arrivals expected = arrivalsOf(serial), parallel = arrivalsOf(output);
    ASSERT_EQ(parallel.id, expected.id);
    for (std::size_t k = 0; k < expected.velocity.size(); ++k) {
        EXPECT_NEAR(parallel.velocity[k], expected.velocity[k], 1e-11);
        EXPECT_NEAR(parallel.position[k], expected.position[k], 1e-14);
    }
    fs::remove_all(serial);
    fs::remove_all(output);
}

/// A refused run: exit status 2, message once on the console, no output directory.
void expectRefused(const std::string& caseName, int ranks, const std::string& message,
                   const std::string& extra = "") {
    const fs::path output = scratch("refused-" + caseName);
    EXPECT_EQ(track(caseName, ranks, output, extra), 2);
    const std::string log = slurp(output.string() + ".log");
    EXPECT_NE(log.find(message), std::string::npos) << log;
    const auto first = log.find("error:");
    EXPECT_NE(first, std::string::npos) << log;
    EXPECT_EQ(log.find("error:", first + 1), std::string::npos) << "printed more than once\n"
                                                                << log;
    EXPECT_FALSE(fs::exists(output));
    fs::remove(output.string() + ".log");
}

TEST(ParallelRefusals, ParallelWithoutProcessorFolders) {
    expectRefused("whole", 2, "-parallel needs a decomposed case (processor0, processor1, ...)");
}

TEST(ParallelRefusals, ProcessorFoldersWithoutParallel) {
    expectRefused("partsOnly", 0,
                  "decomposed into 2 processor folders and has no whole mesh: run `mpirun -np 2 "
                  "slides-track");
    expectRefused("partsOnly", 0, "-parallel`, or `reconstructPar`");
}

TEST(ParallelRefusals, RankCountOtherThanTheProcessorFolders) {
    expectRefused("x2", 3, "decomposed into 2 processor folders but the run has 3 ranks");
}

TEST(ParallelRefusals, ProcessorFoldersHoldingOtherTimes) {
    expectRefused("uneven", 2,
                  "processor1: holds time directories 800 900 but processor0 holds 800");
}

TEST(ParallelRefusals, ErrorOnOneRankEndsEveryRank) {
    // Only processor1/800/U is cut short: rank 1 finds it, every rank stops with its message.
    expectRefused("brokenPart", 2, "brokenPart/processor1/800/U");
}

TEST(ParallelRefusals, InteractionsAcrossRanksAtTheirKeys) {
    // Pairs split over two ranks would need ghost copies (run/run_case.cpp).
    expectRefused("colliding", 2,
                  "key 'collisions.model': colliding particles (ghosts across ranks) is not "
                  "supported in parallel runs yet");
    expectRefused("coulomb", 2,
                  "key 'physics.electromagnetic.coulomb.model': Coulomb forces between particles "
                  "(ghosts across ranks) is not supported in parallel runs yet");
}

TEST(ParallelRefusals, NozzleOnNoRank) {
    expectRefused("nozzleOutside", 2, "key 'nozzle.radius': the nozzle disc");
}

/// A checkpoint is the whole run's (gathered on rank 0, without the parts' mesh locations): a
/// checkpoint of 2 ranks continues on 3, one of 3 ranks serially, and a serial one on 2 ranks,
/// each to the serial run's arrivals and counts bit for bit (the slabs' cases share one
/// dictionary, so one fingerprint). The first runs end a few steps after their last checkpoint,
/// whose steps are all of length dt (an end time on a checkpoint's step would shorten that step
/// by the round-off of the summed time).
TEST(ParallelRuns, RestartOnAnotherRankCountOrSeriallyGivesTheSerialRun) {
    const fs::path twoThenThree = scratch("restart-2-3");
    ASSERT_EQ(track("x2", 2, twoThenThree, "--checkpoint-every 100 --end-time 0.0041"), 0)
        << slurp(twoThenThree.string() + ".log");
    ASSERT_TRUE(fs::exists(twoThenThree / "checkpoint.h5"));
    ASSERT_EQ(track("x3", 3, twoThenThree, "--restart"), 0)
        << slurp(twoThenThree.string() + ".log");
    expectAsSerial(twoThenThree);
    expectConserved(summaryOf(twoThenThree)["particles"]);

    const fs::path threeThenSerial = scratch("restart-3-0");
    ASSERT_EQ(track("x3", 3, threeThenSerial, "--checkpoint-every 150 --end-time 0.0031"), 0)
        << slurp(threeThenSerial.string() + ".log");
    ASSERT_EQ(track("x2", 0, threeThenSerial, "--restart"), 0)
        << slurp(threeThenSerial.string() + ".log");
    expectAsSerial(threeThenSerial);

    const fs::path serialThenTwo = scratch("restart-0-2");
    ASSERT_EQ(track("x2", 0, serialThenTwo, "--checkpoint-every 100 --end-time 0.0021"), 0)
        << slurp(serialThenTwo.string() + ".log");
    ASSERT_EQ(track("x2", 2, serialThenTwo, "--restart"), 0)
        << slurp(serialThenTwo.string() + ".log");
    expectAsSerial(serialThenTwo);
    for (const fs::path& output : {twoThenThree, threeThenSerial, serialThenTwo}) {
        fs::remove_all(output);
        fs::remove(output.string() + ".log");
    }
}

} // namespace
