#include "slides/run/rank_agreement.h"

#include <array>
#include <climits>

namespace slides {

void agreeOnFailure(const RankCommunicator& ranks, const std::function<void()>& check) {
    if (!ranks.parallel()) return check();
    // What failed here: kind 0 none, 1 input (file, line, key, reason), 2 output (message).
    int kind = 0;
    std::array<std::string, 4> parts;
    try {
        check();
    } catch (const InputError& error) {
        kind = 1;
        parts = {error.file(), std::to_string(error.line()), error.key(), error.reason()};
    } catch (const OutputError& error) {
        kind = 2;
        parts[0] = error.what();
    }
    std::array<int, 1> firstFailing{kind != 0 ? ranks.rank() : INT_MAX};
    ranks.min(firstFailing);
    if (firstFailing[0] == INT_MAX) return;
    const int root = firstFailing[0];
    kind = std::stoi(ranks.broadcast(std::to_string(kind), root));
    for (std::string& part : parts) part = ranks.broadcast(part, root);
    if (kind == 2) throw AgreedOutputError(parts[0]);
    throw AgreedInputError(InputError(parts[0], std::stoi(parts[1]), parts[2], parts[3]));
}

} // namespace slides
