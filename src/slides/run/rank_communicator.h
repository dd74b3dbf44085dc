// RankCommunicator: this process's place among the ranks of a parallel run, and the few
// collective and neighbour operations the run needs (MPI, OpenMPI from Debian; C API wrapped).
//
// Reference: MPI 3.1 standard (MPI_Allreduce, MPI_Alltoall, MPI_Isend/MPI_Irecv, MPI_Gatherv).
// A default-constructed communicator is the single rank of a serial run: every operation is the
// identity and MPI is never touched, so serial runs and tests need no mpirun. MPI is started
// only by MpiSession, which the command line creates for `-parallel` (OpenFOAM's flag):
//
//     mpirun -np 4 slides-track CASE -parallel        // RankCommunicator::world(), 4 ranks
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace slides {

using Bytes = std::vector<std::byte>;

/// What this process's MPI communication calls cost: how many, and the wall seconds spent in
/// them (waits for the other ranks included).
struct MpiTally {
    std::uint64_t calls = 0;
    double seconds = 0;
};

class RankCommunicator {
public:
    /// The one rank of a serial run.
    RankCommunicator() = default;
    /// Every rank of the MPI job (MPI_COMM_WORLD); needs a live MpiSession.
    static RankCommunicator world();

    int rank() const { return rank_; }
    int size() const { return size_; }
    /// Whether the run is under MPI (-parallel), even with one rank.
    bool parallel() const { return mpi_; }
    /// The tally of every MPI communication call this process made so far.
    static MpiTally tally();

    /// Σ over ranks, element by element, in place.
    void sum(std::span<double> values) const;
    void sum(std::span<std::uint64_t> values) const;
    std::uint64_t sum(std::uint64_t value) const;
    /// Smallest / largest over ranks, element by element, in place.
    void min(std::span<int> values) const;
    void min(std::span<double> values) const;
    void max(std::span<double> values) const;
    /// Records of `width` doubles laid end to end, the first of each this rank's claim to it
    /// (its rank, or +∞ for none): afterwards every rank holds, for each record, the one of
    /// the rank with the smallest claim, bit for bit (one reduction).
    void keepLowestClaims(std::span<double> records, std::size_t width) const;
    /// outgoing[r] goes to rank r (non-blocking sends and receives between the pairs that have
    /// something to say); returns what each rank sent here, by rank.
    std::vector<Bytes> exchange(const std::vector<Bytes>& outgoing) const;
    /// Every rank's bytes, by rank, on every rank (one collective when every rank has none).
    std::vector<Bytes> allGather(std::span<const std::byte> bytes) const;
    /// Every rank's bytes, by rank, on rank 0 (empty elsewhere).
    std::vector<Bytes> gather(std::span<const std::byte> bytes) const;
    /// Rank root's text on every rank.
    std::string broadcast(const std::string& text, int root) const;
    /// Ends every rank of the job with exit status `status` (after this rank's message).
    [[noreturn]] void abort(int status) const;

private:
    int rank_ = 0;
    int size_ = 1;
    bool mpi_ = false;
};

/// MPI started for the life of this object (MPI_Init_thread, funnelled: OpenMP threads do not
/// call MPI), and finalised after it.
class MpiSession {
public:
    MpiSession(int& argc, char**& argv);
    ~MpiSession();
    MpiSession(const MpiSession&) = delete;
    MpiSession& operator=(const MpiSession&) = delete;
};

} // namespace slides
