// RankExchange: each particle handed to the rank whose part of the mesh holds it, inside the
// step (the exchange stage of a parallel run, run/stepper.h).
//
// Reference: OpenFOAM v1912 Cloud::move (src/lagrangian/basic/Cloud/Cloud.C): a particle whose
// track reaches a processor patch face stops there, is sent to the patch's neighbProcNo with its
// face index in the patch, and goes on from face i of the matching patch there (decomposePar
// orders the faces of the two patches alike); rounds repeat until no particle is in transit on
// any rank. Here the tetrahedron walk toward the particle's end position (carrier/foam_locator.h)
// is what reaches the face; the particle travels with every per-particle array the cloud holds
// for the models that are on, and the stepper's arrays of the step still to be used (its step
// length, the start of its path, temperatures). Particles enter only on the rank whose part
// holds them (integrate/injector.h, splitAmongRanks); a checkpoint's cloud, given to every rank
// alike, stays only on the lowest rank whose part holds each particle (rank 0 when none does),
// so each lands on exactly one rank.
//
//     RankExchange exchange(rankCarrier);  Stepper stepper(scene, rankCarrier, &exchange);
#pragma once

#include "slides/core/particle_cloud.h"
#include "slides/run/processor_clearance.h"
#include "slides/run/rank_carrier.h"

#include <cstdint>
#include <vector>

namespace slides {

/// The stepper's arrays of the current step, one entry a particle (or empty), that travel with it.
struct TravellingArrays {
    std::vector<double>& stepLengths;
    std::vector<Vec3>& startPositions;
    std::vector<Vec3>& startVelocities;
    std::vector<double>& startTemperatures;
    std::vector<double>& gasTemperatures;
};

/// What the exchange cost, over the run on this rank.
struct RankExchangeFigures {
    std::uint64_t particlesSent = 0; ///< crossings of a processor patch
    std::uint64_t bytesSent = 0;
    std::uint64_t rounds = 0;
    double seconds = 0; ///< wall time in the exchange stage
};

class RankExchange {
public:
    explicit RankExchange(const RankCarrier& carrier);

    /// Each particle walks from its location to its position, crossing processor patches until
    /// each is on the rank that holds it. Afterwards its location is its tetrahedron there, or
    /// ≤ −2 outside the mesh through the patch of the case it left by. With startsLocated
    /// (each location is the tetrahedron of the particle's position at the step's start), one
    /// that crossed no processor face (ProcessorClearance) is left at its start's tetrahedron,
    /// to walk at the next step's sample as in a serial run.
    void exchange(ParticleCloud& cloud, TravellingArrays step, bool startsLocated);
    /// Of a cloud every rank holds alike (a checkpoint's), each rank keeps the particles its
    /// part holds (CarrierField::keepHeldHere), located there.
    void keepHeldHere(ParticleCloud& cloud, TravellingArrays step);
    /// Whether no rank holds a particle (collective).
    bool everyRankEmpty(std::size_t particles) const;

    const RankCommunicator& ranks() const { return carrier_.ranks(); }
    const RankExchangeFigures& figures() const { return figures_; }

private:
    /// The location of point walking from location on this part: found, or the processor patch
    /// face it reached (transitFace), or outside through a patch of the case.
    std::int32_t walk(const Vec3& point, std::int32_t location, int& transitFace) const;
    /// This rank's processor patch shared with rank, −1 if none.
    int patchTowards(int rank) const;

    const RankCarrier& carrier_;
    ProcessorClearance clearance_;
    RankExchangeFigures figures_;
};

} // namespace slides
