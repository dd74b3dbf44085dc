// libFuzzer target: an OpenFOAM case with one mesh or field file replaced by arbitrary bytes
// (tests/support/fuzz_entries.h); the box mesh in ASCII, or in binary with FUZZ_BINARY.
#include "../../tests/support/fuzz_entries.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    slides::fuzz::readFoamCaseWithReplacedFile({reinterpret_cast<const char*>(data), size},
                                               FUZZ_MESH);
    return 0;
}
