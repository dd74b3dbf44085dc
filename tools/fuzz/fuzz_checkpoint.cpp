// libFuzzer target: a checkpoint.h5 of arbitrary bytes, read as a restart reads it
// (tests/support/fuzz_entries.h); seeds in tests/fuzz/regressions/checkpoint/.
#include "../../tests/support/fuzz_entries.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    slides::fuzz::readCheckpointBytes({reinterpret_cast<const char*>(data), size});
    return 0;
}
