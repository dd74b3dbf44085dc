// ProgressDisplay: a progress bar with ETA on a terminal, plain periodic lines otherwise.
//
//     [#############.................]  43%  t = 1.23e-02 s  active 1840  ETA 4 s
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace slides {

class ProgressDisplay {
public:
    /// stream: where to draw (stderr); quiet: draw nothing.
    ProgressDisplay(std::FILE* stream, bool quiet);

    /// fraction in [0, 1] of the run done; the rest is shown as it is.
    void update(double fraction, double time, std::size_t activeParticles);
    /// Ends the bar's line on a terminal.
    void finish();

private:
    using Clock = std::chrono::steady_clock;
    std::FILE* stream_;
    bool quiet_;
    bool terminal_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point lastDrawn_ = Clock::now();
    int lastDecile_ = 0;
    bool drawn_ = false;
};

} // namespace slides
