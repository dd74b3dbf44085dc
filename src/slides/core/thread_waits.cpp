#include "slides/core/thread_waits.h"

#include <cstdlib>
#include <unistd.h>

namespace slides {

void sleepWhileWaitingForWork(char** argv) {
    if (std::getenv("OMP_WAIT_POLICY") != nullptr) return;
    if (setenv("OMP_WAIT_POLICY", "PASSIVE", 1) != 0) return;
    execv("/proc/self/exe", argv); // returns only on failure
}

} // namespace slides
