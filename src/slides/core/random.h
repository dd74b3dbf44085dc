// Counter-based random numbers (Philox4x32-10, Salmon et al. 2011, via Random123).
//
// A stream is keyed by (seed, particle id, event counter): the numbers a particle draws do not
// depend on how many other particles exist, on the order they are processed or on the thread
// count, and a restarted run draws the same numbers again.
#pragma once

#include <Random123/philox.h>

#include <cstdint>

namespace slides {

/// Purpose of a draw, so independent events of one particle never share numbers.
enum class RandomPurpose : std::uint32_t { injection = 1, radius = 2, eddy = 3, chargeSign = 4 };

class RandomStream {
public:
    RandomStream(std::uint64_t seed, std::uint64_t particleId, RandomPurpose purpose,
                 std::uint32_t eventCounter = 0);

    /// Uniform on the open interval (0, 1): never exactly 0 or 1, so logarithms are safe.
    double uniform();
    /// Standard normal deviate (Box–Muller on two uniforms).
    double normal();

private:
    using Generator = r123::Philox4x32;
    Generator::key_type key_;
    Generator::ctr_type counter_;
    Generator::ctr_type block_;
    int used_ = 4;
};

} // namespace slides
