// Rank agreement: an error one rank finds in its part of the input ends every rank alike.
//
// A rank that reads a bad processor*/ folder, or fails to open the output, must not leave the
// others waiting in a collective operation: the check runs on every rank, the ranks agree on
// whether any failed, and each then throws the error of the lowest rank that failed, marked
// AgreedError, which the command line prints once (rank 0) with exit status 2. An error that
// every rank finds alike at the same point (the dictionary's, the scene analysis') is marked
// the same way. A failure on one rank alone later in the run ends the job by MPI_Abort.
//
//     agreeOnFailure(ranks, [&] { carrier = readMyPart(); });
#pragma once

#include "slides/core/error.h"
#include "slides/io/atomic_file.h"
#include "slides/run/rank_communicator.h"

#include <functional>

namespace slides {

/// Marks an error that every rank of the job throws alike.
class AgreedError {
public:
    virtual ~AgreedError() = default;
};

class AgreedInputError : public InputError, public AgreedError {
public:
    explicit AgreedInputError(const InputError& error)
        : InputError(error.file(), error.line(), error.key(), error.reason()) {}
};

class AgreedOutputError : public OutputError, public AgreedError {
public:
    using OutputError::OutputError;
};

/// Runs check on every rank; if it throws InputError or OutputError on any rank, every rank
/// throws the lowest failing rank's error as AgreedInputError / AgreedOutputError. Serial: runs
/// check and lets its errors pass.
void agreeOnFailure(const RankCommunicator& ranks, const std::function<void()>& check);

} // namespace slides
