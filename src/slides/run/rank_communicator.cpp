#include "slides/run/rank_communicator.h"

// The C API only (OpenMPI would add its deprecated C++ bindings, which need another library).
#define OMPI_SKIP_MPICXX 1
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace slides {

namespace {

void check(int status, const char* what) {
    if (status != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

int countOf(std::size_t bytes) {
    if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max()))
        throw std::runtime_error("MPI: more than 2 GiB in one message");
    return static_cast<int>(bytes);
}

/// Offsets of counts laid end to end, and their total.
std::vector<int> displacements(const std::vector<int>& counts, std::size_t& total) {
    std::vector<int> offsets(counts.size(), 0);
    total = 0;
    for (std::size_t r = 0; r < counts.size(); ++r) {
        offsets[r] = countOf(total);
        total += static_cast<std::size_t>(counts[r]);
    }
    return offsets;
}

std::vector<Bytes> split(const Bytes& all, const std::vector<int>& counts,
                         const std::vector<int>& offsets) {
    std::vector<Bytes> parts(counts.size());
    for (std::size_t r = 0; r < counts.size(); ++r)
        parts[r].assign(all.begin() + offsets[r], all.begin() + offsets[r] + counts[r]);
    return parts;
}

MpiTally processTally; // every communicator of this process alike

/// The status of an MPI communication call, its count and wall time added to the tally.
template <class Call> int timed(Call call) {
    const auto start = std::chrono::steady_clock::now();
    const int status = call();
    ++processTally.calls;
    processTally.seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return status;
}

} // namespace

MpiTally RankCommunicator::tally() { return processTally; }

RankCommunicator RankCommunicator::world() {
    RankCommunicator ranks;
    check(MPI_Comm_rank(MPI_COMM_WORLD, &ranks.rank_), "MPI_Comm_rank");
    check(MPI_Comm_size(MPI_COMM_WORLD, &ranks.size_), "MPI_Comm_size");
    ranks.mpi_ = true;
    return ranks;
}

void RankCommunicator::sum(std::span<double> values) const {
    if (!mpi_ || values.empty()) return;
    check(timed([&] {
              return MPI_Allreduce(MPI_IN_PLACE, values.data(), countOf(values.size()), MPI_DOUBLE,
                                   MPI_SUM, MPI_COMM_WORLD);
          }),
          "MPI_Allreduce");
}

void RankCommunicator::sum(std::span<std::uint64_t> values) const {
    if (!mpi_ || values.empty()) return;
    check(timed([&] {
              return MPI_Allreduce(MPI_IN_PLACE, values.data(), countOf(values.size()),
                                   MPI_UINT64_T, MPI_SUM, MPI_COMM_WORLD);
          }),
          "MPI_Allreduce");
}

std::uint64_t RankCommunicator::sum(std::uint64_t value) const {
    sum(std::span(&value, 1));
    return value;
}

void RankCommunicator::min(std::span<int> values) const {
    if (!mpi_ || values.empty()) return;
    check(timed([&] {
              return MPI_Allreduce(MPI_IN_PLACE, values.data(), countOf(values.size()), MPI_INT,
                                   MPI_MIN, MPI_COMM_WORLD);
          }),
          "MPI_Allreduce");
}

void RankCommunicator::min(std::span<double> values) const {
    if (!mpi_ || values.empty()) return;
    check(timed([&] {
              return MPI_Allreduce(MPI_IN_PLACE, values.data(), countOf(values.size()), MPI_DOUBLE,
                                   MPI_MIN, MPI_COMM_WORLD);
          }),
          "MPI_Allreduce");
}

void RankCommunicator::max(std::span<double> values) const {
    if (!mpi_ || values.empty()) return;
    check(timed([&] {
              return MPI_Allreduce(MPI_IN_PLACE, values.data(), countOf(values.size()), MPI_DOUBLE,
                                   MPI_MAX, MPI_COMM_WORLD);
          }),
          "MPI_Allreduce");
}

void RankCommunicator::keepLowestClaims(std::span<double> records, std::size_t width) const {
    if (!mpi_ || records.empty()) return;
    MPI_Datatype record = MPI_DATATYPE_NULL;
    check(MPI_Type_contiguous(countOf(width), MPI_DOUBLE, &record), "MPI_Type_contiguous");
    check(MPI_Type_commit(&record), "MPI_Type_commit");
    // inout[k] = in[k] where in's claim is smaller: commutative and associative.
    MPI_User_function* lowestClaim = [](void* in, void* inout, int* count, MPI_Datatype* type) {
        int bytes = 0;
        MPI_Type_size(*type, &bytes);
        const auto size = static_cast<std::size_t>(bytes) / sizeof(double);
        const auto* from = static_cast<const double*>(in);
        auto* into = static_cast<double*>(inout);
        for (int k = 0; k < *count; ++k, from += size, into += size)
            if (from[0] < into[0]) std::copy(from, from + size, into);
    };
    MPI_Op operation = MPI_OP_NULL;
    check(MPI_Op_create(lowestClaim, 1, &operation), "MPI_Op_create");
    const int status = timed([&] {
        return MPI_Allreduce(MPI_IN_PLACE, records.data(), countOf(records.size() / width), record,
                             operation, MPI_COMM_WORLD);
    });
    MPI_Op_free(&operation);
    MPI_Type_free(&record);
    check(status, "MPI_Allreduce");
}

std::vector<Bytes> RankCommunicator::exchange(const std::vector<Bytes>& outgoing) const {
    if (!mpi_) return outgoing;
    std::vector<int> sendCounts(static_cast<std::size_t>(size_)), receiveCounts(sendCounts.size());
    for (std::size_t r = 0; r < sendCounts.size(); ++r) sendCounts[r] = countOf(outgoing[r].size());
    check(timed([&] {
              return MPI_Alltoall(sendCounts.data(), 1, MPI_INT, receiveCounts.data(), 1, MPI_INT,
                                  MPI_COMM_WORLD);
          }),
          "MPI_Alltoall");
    std::vector<Bytes> incoming(sendCounts.size());
    std::vector<MPI_Request> requests;
    for (int r = 0; r < size_; ++r) {
        incoming[r].resize(static_cast<std::size_t>(receiveCounts[r]));
        if (receiveCounts[r] == 0) continue;
        requests.emplace_back();
        check(MPI_Irecv(incoming[r].data(), receiveCounts[r], MPI_BYTE, r, 0, MPI_COMM_WORLD,
                        &requests.back()),
              "MPI_Irecv");
    }
    for (int r = 0; r < size_; ++r) {
        if (sendCounts[r] == 0) continue;
        requests.emplace_back();
        check(MPI_Isend(outgoing[r].data(), sendCounts[r], MPI_BYTE, r, 0, MPI_COMM_WORLD,
                        &requests.back()),
              "MPI_Isend");
    }
    check(timed([&] {
              return MPI_Waitall(static_cast<int>(requests.size()), requests.data(),
                                 MPI_STATUSES_IGNORE);
          }),
          "MPI_Waitall");
    return incoming;
}

std::vector<Bytes> RankCommunicator::allGather(std::span<const std::byte> bytes) const {
    if (!mpi_) return {Bytes(bytes.begin(), bytes.end())};
    std::vector<int> counts(static_cast<std::size_t>(size_));
    const int count = countOf(bytes.size());
    check(timed([&] {
              return MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, MPI_COMM_WORLD);
          }),
          "MPI_Allgather");
    std::size_t total = 0;
    const auto offsets = displacements(counts, total);
    if (total == 0) return std::vector<Bytes>(counts.size());
    Bytes all(total);
    check(timed([&] {
              return MPI_Allgatherv(bytes.data(), count, MPI_BYTE, all.data(), counts.data(),
                                    offsets.data(), MPI_BYTE, MPI_COMM_WORLD);
          }),
          "MPI_Allgatherv");
    return split(all, counts, offsets);
}

std::vector<Bytes> RankCommunicator::gather(std::span<const std::byte> bytes) const {
    if (!mpi_) return {Bytes(bytes.begin(), bytes.end())};
    std::vector<int> counts(static_cast<std::size_t>(size_));
    const int count = countOf(bytes.size());
    check(timed([&] {
              return MPI_Gather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, 0, MPI_COMM_WORLD);
          }),
          "MPI_Gather");
    std::size_t total = 0;
    const auto offsets = displacements(counts, total);
    Bytes all(rank_ == 0 ? total : 0);
    check(timed([&] {
              return MPI_Gatherv(bytes.data(), count, MPI_BYTE, all.data(), counts.data(),
                                 offsets.data(), MPI_BYTE, 0, MPI_COMM_WORLD);
          }),
          "MPI_Gatherv");
    if (rank_ != 0) return {};
    return split(all, counts, offsets);
}

std::string RankCommunicator::broadcast(const std::string& text, int root) const {
    if (!mpi_) return text;
    int length = countOf(text.size());
    check(timed([&] { return MPI_Bcast(&length, 1, MPI_INT, root, MPI_COMM_WORLD); }), "MPI_Bcast");
    std::string result = rank_ == root ? text : std::string(static_cast<std::size_t>(length), ' ');
    check(timed([&] { return MPI_Bcast(result.data(), length, MPI_CHAR, root, MPI_COMM_WORLD); }),
          "MPI_Bcast");
    return result;
}

void RankCommunicator::abort(int status) const {
    if (mpi_) MPI_Abort(MPI_COMM_WORLD, status);
    std::exit(status);
}

MpiSession::MpiSession(int& argc, char**& argv) {
    int provided = 0;
    check(MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
}

MpiSession::~MpiSession() { MPI_Finalize(); }

} // namespace slides
