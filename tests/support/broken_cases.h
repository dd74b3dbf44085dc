// Broken copies of the default case: one piece of its dictionary replaced, run through the
// command line, which must refuse it with one message naming file, line and key, exit status 2,
// and no output directory; RefusedCase runs a table of them.
#pragma once

#include "case_runs.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace slides::test {

struct BrokenCase {
    const char* name;
    const char* from;     ///< text of the default case to replace
    const char* to;       ///< its replacement
    int lineOffset;       ///< error line relative to the line where `from` starts
    const char* expected; ///< substring of the one error message, after "file:line: "
};

/// Writes a copy of the default case's dictionary with one line replaced.
inline void writeBrokenCase(const ScratchDirectory& scratch, const std::string& from,
                            const std::string& to) {
    std::string text = slurp(defaultCase / "constant" / "slidesProperties");
    const auto at = text.find(from);
    ASSERT_NE(at, std::string::npos) << from;
    text.replace(at, from.size(), to);
    std::ofstream(scratch.path / "constant" / "slidesProperties") << text;
}

inline void expectRefused(const BrokenCase& broken) {
    ScratchDirectory scratch(broken.name);
    writeBrokenCase(scratch, broken.from, broken.to);
    const std::string original = slurp(defaultCase / "constant" / "slidesProperties");
    const auto line =
        1 + std::count(original.begin(), original.begin() + original.find(broken.from), '\n') +
        broken.lineOffset;
    const auto log = scratch.path / "log";
    EXPECT_EQ(runCli(scratch.path.string() + " --quiet", log), 2);
    const std::string message = slurp(log);
    const std::string where = "slidesProperties:" + std::to_string(line) + ": ";
    EXPECT_NE(message.find(where + broken.expected), std::string::npos)
        << "expected '" << where << broken.expected << "' in:\n"
        << message;
    EXPECT_EQ(message.find("error:"), message.rfind("error:")) << "one message: " << message;
    EXPECT_FALSE(std::filesystem::exists(scratch.path / "slides"))
        << "bad input must not create output";
}

/// A table of broken cases, each refused as expectRefused says; a test program instantiates it
/// with its table: INSTANTIATE_TEST_SUITE_P(Group, RefusedCase, ValuesIn(table), brokenCaseName).
class RefusedCase : public ::testing::TestWithParam<BrokenCase> {};

TEST_P(RefusedCase, WithExitStatus2AndOneMessageNamingFileLineAndKeyBeforeAnythingIsWritten) {
    expectRefused(GetParam());
}

inline std::string brokenCaseName(const ::testing::TestParamInfo<BrokenCase>& info) {
    return info.param.name;
}

} // namespace slides::test
