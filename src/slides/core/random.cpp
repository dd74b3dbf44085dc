#include "slides/core/random.h"

#include <cmath>
#include <numbers>

namespace slides {

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t particleId, RandomPurpose purpose,
                           std::uint32_t eventCounter)
    : key_{{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32)}},
      counter_{{static_cast<std::uint32_t>(particleId),
                static_cast<std::uint32_t>(particleId >> 32), eventCounter,
                static_cast<std::uint32_t>(purpose) << 24}} {}

double RandomStream::uniform() {
    if (used_ == 4) {
        block_ = Generator{}(counter_, key_);
        ++counter_[3]; // low 24 bits count blocks within this stream
        used_ = 0;
    }
    // 32 random bits mapped to the centres of 2^32 bins: (k + 0.5) / 2^32 lies in (0, 1).
    return (static_cast<double>(block_[used_++]) + 0.5) * 0x1p-32;
}

double RandomStream::normal() {
    const double radius = std::sqrt(-2.0 * std::log(uniform()));
    return radius * std::cos(2.0 * std::numbers::pi * uniform());
}

} // namespace slides
