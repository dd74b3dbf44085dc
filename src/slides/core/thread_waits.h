// Waiting threads sleep: the OpenMP threads of a run block in the kernel between parallel loops
// instead of spinning, so that a core busy with another program does not stretch every wait.
// Reference: OpenMP 5.1, OMP_WAIT_POLICY; GNU libgomp reads it once, when the library loads.
//
//     OMP_WAIT_POLICY=ACTIVE slides-track CASE    // spin instead (a machine of one's own)
#pragma once

namespace slides {

/// When the environment does not set OMP_WAIT_POLICY, sets it to PASSIVE and starts the program
/// again with the same arguments (the only way to reach libgomp, already loaded); returns when
/// the policy is the user's, or if starting again failed (the run then keeps the default).
void sleepWhileWaitingForWork(char** argv);

} // namespace slides
