// Fuzz entry points: what the fuzz targets (tools/fuzz/) feed arbitrary bytes to, shared with
// the regression test that replays every input they once crashed on (tests/fuzz/).
//
// The contract under test: any input either parses or raises the one InputError naming the
// file and line; it never crashes, hangs, reads out of bounds or throws anything else.
#pragma once

#include "slides/config/dictionary.h"
#include "slides/config/scene_reader.h"
#include "slides/core/error.h"

#include <string_view>

namespace slides::fuzz {

/// A case dictionary (constant/slidesProperties) given as text: parse it and build the Scene.
inline void readDictionaryText(std::string_view text) {
    try {
        const Dictionary dictionary =
            Dictionary::parseString(text, "fuzz/constant/slidesProperties");
        (void)sceneFromDictionary(dictionary, "fuzz");
    } catch (const InputError&) {
        // the expected outcome for a bad input
    }
}

} // namespace slides::fuzz
