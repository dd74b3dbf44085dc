// ctest-labels: robustness config
// Dictionaries built to break the reader: nesting deep enough to overflow the stack, files and
// value counts that would fill the memory, bytes that print as nothing (a NUL, a byte-order
// mark) and an #include through a loop of symbolic links. Each ends in one InputError that says
// what is wrong, located at file, line and key.
#include "slides/config/dictionary.h"
#include "slides/core/error.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <unistd.h>

namespace slides {
namespace {

namespace fs = std::filesystem;

InputError errorOf(const std::function<void()>& action) {
    try {
        action();
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "no InputError";
    return InputError("", 0, "", "");
}

std::string parseMessage(const std::string& text) {
    return errorOf([&] { Dictionary::parseString(text, "case/slidesProperties"); }).what();
}

struct ScratchFolder {
    fs::path path = fs::temp_directory_path() / ("slides_hostile_" + std::to_string(::getpid()));
    ScratchFolder() {
        fs::remove_all(path);
        fs::create_directories(path);
    }
    ~ScratchFolder() { fs::remove_all(path); }
};

// 30 000 '(' took the recursive parser 30 000 frames deep, past the stack's end (SIGSEGV).
TEST(HostileDictionary, DeeplyNestedListIsRefused) {
    EXPECT_EQ(parseMessage("x " + std::string(30'000, '(') + "\n"),
              "case/slidesProperties:1: key 'x': '(' nested more than 64 deep");
}

TEST(HostileDictionary, DeeplyNestedDictionariesAreRefused) {
    std::string text;
    for (int level = 0; level < 30'000; ++level) text += "a {\n";
    const InputError error = errorOf([&] { Dictionary::parseString(text, "case/d"); });
    EXPECT_EQ(error.line(), 65);
    EXPECT_EQ(error.reason(), "'{' nested more than 64 deep");
}

TEST(HostileDictionary, NestingAsDeepAsTheBoundIsRead) {
    const Dictionary top = Dictionary::parseString(
        "x " + std::string(63, '(') + "1" + std::string(63, ')') + ";\n", "case/d");
    EXPECT_EQ(top.find("x")->items.size(), 1u);
}

// A 20 MB dictionary took 883 MB of memory per 50 MB: refused before it is read.
TEST(HostileDictionary, HugeFileIsRefusedBeforeItIsRead) {
    const ScratchFolder folder;
    const fs::path file = folder.path / "slidesProperties";
    {
        std::ofstream out(file);
        const std::string line = "x (1 2 3 4 5 6 7 8 9 10 11 12 13 14 15 16 17 18 19 20);\n";
        for (std::size_t size = 0; size < (std::size_t{20} << 20); size += line.size()) out << line;
    }
    EXPECT_EQ(std::string(errorOf([&] { Dictionary::parseFile(file); }).what()),
              file.string() +
                  ": cannot read the dictionary: " + std::to_string(fs::file_size(file)) +
                  " bytes, more than the 16777216 of a case dictionary");
}

TEST(HostileDictionary, UniformListOfTooManyValuesIsRefused) {
    EXPECT_EQ(parseMessage("a 1;\nx 2000000{0};\n"),
              "case/slidesProperties:2: key 'x': more than 1000000 values in the dictionary");
}

// Each reference doubles the list: 2^30 values from 30 short lines.
TEST(HostileDictionary, ReferencesDoublingAListAreRefused) {
    std::string text = "a0 (1 2);\n";
    for (int level = 1; level <= 30; ++level)
        text += "a" + std::to_string(level) + " ($a" + std::to_string(level - 1) + " $a" +
                std::to_string(level - 1) + ");\n";
    const InputError error = errorOf([&] { Dictionary::parseString(text, "case/d"); });
    EXPECT_EQ(error.reason(), "more than 1000000 values in the dictionary");
    // a_k holds 2^(k+1) numbers, a_0 … a_17 together 2^19 − 2 and their copies as many again:
    // the dictionary passes 10^6 values on a17's line.
    EXPECT_EQ(error.line(), 18);
}

// A NUL byte went into the message as it was, cutting the line short in a terminal.
TEST(HostileDictionary, NulByteIsShownEscaped) {
    EXPECT_EQ(parseMessage(std::string("a 1;\nb \0;\n", 9)),
              "case/slidesProperties:2: key 'b': unexpected character '\\x00'");
}

// A byte-order mark (Windows editors write one) glues to the first keyword and printed as
// nothing: the message named a key that looked right.
TEST(HostileDictionary, ByteOrderMarkIsShownEscaped) {
    const Dictionary dictionary =
        Dictionary::parseString("\xEF\xBB\xBFparticles { density 2500; }\n", "case/d");
    EXPECT_EQ(
        std::string(errorOf([&] { dictionary.integer("\xEF\xBB\xBFparticles"); }).what()),
        "case/d:1: key '\\uFEFFparticles': expected a whole number, found a dictionary { ... }");
}

TEST(HostileDictionary, InvalidUtf8IsShownEscapedAndValidUtf8Kept) {
    EXPECT_EQ(std::string(InputError("f", 3, "ε\xff", "bad").what()), "f:3: key 'ε\\xFF': bad");
}

// The loop said "no such file", though the link is there.
TEST(HostileDictionary, IncludeThroughASymbolicLinkLoop) {
    const ScratchFolder folder;
    fs::create_symlink(folder.path / "loopB", folder.path / "loopA");
    fs::create_symlink(folder.path / "loopA", folder.path / "loopB");
    const fs::path main = folder.path / "slidesProperties";
    std::ofstream(main) << "a 1;\n#include \"loopA\"\n";
    EXPECT_EQ(std::string(errorOf([&] { Dictionary::parseFile(main); }).what()),
              main.string() + ":2: cannot read included file '" + (folder.path / "loopA").string() +
                  "': a loop of symbolic links");
}

} // namespace
} // namespace slides
