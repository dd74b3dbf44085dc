// libFuzzer target: arbitrary bytes as a case dictionary (tests/support/fuzz_entries.h).
#include "../../tests/support/fuzz_entries.h"

#include <cstddef>
#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    slides::fuzz::readDictionaryText({reinterpret_cast<const char*>(data), size});
    return 0;
}
