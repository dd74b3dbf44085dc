#include "slides/io/progress.h"

#include <algorithm>
#include <cmath>
#include <unistd.h>

namespace slides {

ProgressDisplay::ProgressDisplay(std::FILE* stream, bool quiet)
    : stream_(stream), quiet_(quiet), terminal_(isatty(fileno(stream)) != 0) {}

void ProgressDisplay::update(double fraction, double time, std::size_t activeParticles) {
    if (quiet_) return;
    fraction = std::clamp(fraction, 0.0, 1.0);
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double remaining = fraction > 0 ? elapsed * (1 - fraction) / fraction : 0;
    if (terminal_) {
        if (drawn_ && now - lastDrawn_ < std::chrono::milliseconds(100)) return;
        constexpr int width = 30;
        const int filled = static_cast<int>(std::round(fraction * width));
        std::fprintf(stream_, "\r[%s%s] %3.0f%%  t = %.3e s  active %zu  ETA %.0f s ",
                     std::string(filled, '#').c_str(), std::string(width - filled, '.').c_str(),
                     100 * fraction, time, activeParticles, remaining);
    } else {
        // Plain lines for logs: one per 10 % of the run.
        const int decile = static_cast<int>(fraction * 10);
        if (drawn_ && decile <= lastDecile_) return;
        lastDecile_ = decile;
        std::fprintf(stream_, "progress %3.0f%%  t = %.3e s  active %zu  elapsed %.1f s\n",
                     100 * fraction, time, activeParticles, elapsed);
    }
    std::fflush(stream_);
    lastDrawn_ = now;
    drawn_ = true;
}

void ProgressDisplay::finish() {
    if (!quiet_ && terminal_ && drawn_) std::fputc('\n', stream_);
}

} // namespace slides
