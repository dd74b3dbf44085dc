// Scenes for tests read from a case dictionary, as a user's slidesProperties is read: the keys'
// validation and defaults apply.
#pragma once

#include "slides/config/dictionary.h"
#include "slides/config/scene_reader.h"

#include <string>

namespace slides::test {

/// Ten particles of 10 µm (ρp 1000) released at t = 0 from a 1 mm nozzle in a 2 m box, steps of
/// 0.1 ms to 10 ms, with this carrier block's entries and, when given, this physics block's.
inline Scene sceneWithCarrier(const std::string& carrier, const std::string& physics = "") {
    const std::string text =
        "fluid { density 1.2; kinematicViscosity 1.5e-5; }\n"
        "nozzle { centre (0 0 0); axis (1 0 0); radius 1e-3; }\n"
        "carrier { " +
        carrier +
        " }\n"
        "particles { count 10; density 1000; radiusDistribution { type fixed; value 1e-5; } }\n"
        "injection { mode allAtStart; seed 1; }\n" +
        (physics.empty() ? "" : "physics { " + physics + " }\n") +
        "time { dt 1e-4; endTime 0.01; }\n"
        "domain { min (-1 -1 -1); max (1 1 1); }\n"
        "surfaces { }\n"
        "output { interval 0.01; }\n";
    return sceneFromDictionary(Dictionary::parseString(text, "slidesProperties"), ".");
}

} // namespace slides::test
