// Error: the one typed error of the library; only the command line turns it into exit status 2.
//
// An input error carries where it came from: file, line and key, so a user finds the bad entry
// at once. Its message shows every byte: control bytes, invalid UTF-8 and invisible characters
// (a byte-order mark) are escaped as \xNN or \uNNNN. A run stopped because a particle's state
// stopped being finite (forces that overflow, a step far above the stable one) is a
// NonFiniteState, exit status 1 but not an internal failure. Internal failures (broken
// invariants) are ordinary std::logic_error / runtime_error.
#pragma once

#include <stdexcept>
#include <string>

namespace slides {

class InputError : public std::runtime_error {
public:
    /// file: path as the user gave it; line: 1-based, 0 when unknown; key: dictionary path
    /// such as "particles.radiusDistribution.mean", empty when the error is not about a key.
    InputError(std::string file, int line, std::string key, const std::string& message);

    const std::string& file() const { return file_; }
    int line() const { return line_; }
    const std::string& key() const { return key_; }
    /// What was wrong, without the location prefix.
    const std::string& reason() const { return reason_; }

private:
    std::string file_;
    int line_;
    std::string key_;
    std::string reason_;
};

/// A particle's position or velocity is no longer finite: the run stops there instead of carrying
/// NaN on (the message names the particle, the time and its state).
class NonFiniteState : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

} // namespace slides
