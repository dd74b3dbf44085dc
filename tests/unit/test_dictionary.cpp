// ctest-labels: foundation config
// The OpenFOAM dictionary parser (config/dictionary.h): the syntax OpenFOAM v1912 accepts, read
// from a complete case file with an #include, and one error located at file, line and key path
// for each kind of malformed input or mistyped value.
#include "slides/config/dictionary.h"

#include "slides/core/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <unistd.h>

namespace slides {
namespace {

namespace fs = std::filesystem;

/// A fresh directory per test, removed afterwards.
class TemporaryDirectory {
public:
    TemporaryDirectory() {
        const auto* test = testing::UnitTest::GetInstance()->current_test_info();
        path_ = fs::temp_directory_path() /
                ("slides_dictionary_" + std::to_string(::getpid()) + "_" + test->name());
        fs::remove_all(path_);
        fs::create_directories(path_);
    }
    ~TemporaryDirectory() {
        std::error_code ignored;
        fs::remove_all(path_, ignored);
    }
    TemporaryDirectory(const TemporaryDirectory&) = delete;
    TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;

    fs::path write(const std::string& relative, const std::string& text) const {
        const fs::path file = path_ / relative;
        fs::create_directories(file.parent_path());
        std::ofstream(file) << text;
        return file;
    }

private:
    fs::path path_;
};

/// The InputError that parsing text throws (fails the test if none is thrown).
InputError parseError(const std::string& text, const std::string& file = "case/slidesProperties") {
    try {
        Dictionary::parseString(text, file);
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "no InputError for:\n" << text;
    return InputError("", -1, "", "no error");
}

template <typename Read> InputError readError(Read read) {
    try {
        read();
    } catch (const InputError& error) {
        return error;
    }
    ADD_FAILURE() << "no InputError from the read";
    return InputError("", -1, "", "no error");
}

std::vector<double> exponents(const DictEntry* entry) {
    if (!entry || !entry->dimensions) return {};
    return entry->dimensions->exponents;
}

// ---------------------------------------------------------------------------------------------
// A complete case file

const char* caseText = R"(/*----------------------------*- C++ -*-------------------------------*\
  SLIDES-track test case: every syntax the parser accepts.
\*---------------------------------------------------------------------*/
FoamFile
{
    version     2.0;
    format      ascii;
    class       dictionary;
    object      slidesProperties;
}
// * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * * //

standoff        0.06;           // [m]
count           8000;
tiny            1e-5;
negative        -3;
half            .5;
title           "spray \"A\" test";
buoyancy        on;
stopWhenDone    no;
path/like:word  analyticJetCoeffs;

#include "include/common"

fluid
{
    density     [1 -3 0 0 0 0 0] 1.1;
    nu          1e-5 [0 2 -1 0 0];   /* a dimension set may follow the value */
    inner { deeper { value 42; } }
}

carrier
{
    type        analyticJet;
    velocity    $..standoff;
    copyOfFluid $fluid;
    density     $fluid.density;
    deep        ${fluid.inner.deeper.value};
    fromTop     $:fluid.inner.deeper.value;
    analyticJetCoeffs
    {
        profile     axisymmetric;
        speed       $..velocity;
        again       $velocity;
        $:fluid.inner;
    }
}

lists
{
    point       ($standoff 0 -1);
    counted     3(1 2 3);
    uniform     4{0.5};
    nested      ((1 2) (3 4 5) ());
    words       (alpha "beta gamma" delta);
    long        2
    (
        7 8
    );
    mixed       uniform (0 0 1);
    table       ((0 (1 0 0)) (1 (2 0 0)));
};

// ************************************************************************* //
)";

const char* commonText = R"(FoamFile { version 2.0; format ascii; class dictionary; object common; }
sharedRadius    2e-3;
included
{
    flag    yes;
    ref     $standoff;
}
)";

class CaseFile : public testing::Test {
protected:
    CaseFile()
        : file(directory.write("constant/slidesProperties", caseText)),
          common(directory.write("constant/include/common", commonText)),
          top(Dictionary::parseFile(file)) {}

    TemporaryDirectory directory;
    fs::path file;
    fs::path common;
    Dictionary top;
};

TEST_F(CaseFile, HeaderIsSeparateFromTheEntries) {
    ASSERT_NE(top.header(), nullptr);
    EXPECT_EQ(top.header()->word("object"), "slidesProperties"); // not the included file's
    EXPECT_DOUBLE_EQ(top.header()->scalar("version"), 2.0);
    EXPECT_FALSE(top.has("FoamFile"));
    const std::vector<std::string> expected{
        "standoff", "count",    "tiny",         "negative",       "half",
        "title",    "buoyancy", "stopWhenDone", "path/like:word", "sharedRadius",
        "included", "fluid",    "carrier",      "lists"};
    EXPECT_EQ(top.keys(), expected);
}

TEST_F(CaseFile, ScalarsWordsStringsAndSwitches) {
    EXPECT_EQ(top.file(), file.string());
    EXPECT_EQ(top.path(), "");
    EXPECT_EQ(top.line(), 0);
    EXPECT_DOUBLE_EQ(top.scalar("standoff"), 0.06);
    EXPECT_EQ(top.lineOf("standoff"), 13);
    EXPECT_EQ(top.integer("count"), 8000);
    EXPECT_TRUE(top.find("count")->items.front().writtenAsInteger());
    EXPECT_FALSE(top.find("standoff")->items.front().writtenAsInteger());
    EXPECT_DOUBLE_EQ(top.scalar("tiny"), 1e-5);
    EXPECT_EQ(top.integer("negative"), -3);
    EXPECT_DOUBLE_EQ(top.scalar("half"), 0.5);
    EXPECT_EQ(top.text("title"), "spray \"A\" test");
    EXPECT_TRUE(top.boolean("buoyancy"));
    EXPECT_FALSE(top.boolean("stopWhenDone"));
    EXPECT_EQ(top.word("path/like:word"), "analyticJetCoeffs");
}

TEST_F(CaseFile, IncludedEntriesJoinTheIncludingDictionary) {
    EXPECT_DOUBLE_EQ(top.scalar("sharedRadius"), 2e-3);
    const DictEntry* included = top.find("included");
    ASSERT_NE(included, nullptr);
    EXPECT_EQ(included->file, common.string());
    EXPECT_EQ(included->line, 3);
    EXPECT_EQ(top.find("standoff")->file, file.string());
    EXPECT_TRUE(top.subDict("included").boolean("flag"));
    // a reference in the included file sees the including file's earlier entries
    EXPECT_DOUBLE_EQ(top.subDict("included").scalar("ref"), 0.06);
    // errors about included entries point into the included file
    const InputError error = readError([&] { top.subDict("included").integer("flag"); });
    EXPECT_EQ(error.file(), common.string());
    EXPECT_EQ(error.line(), 5);
    EXPECT_EQ(error.key(), "included.flag");
}

TEST_F(CaseFile, NestedDictionariesAndDimensionSets) {
    const Dictionary& fluid = top.subDict("fluid");
    EXPECT_EQ(fluid.path(), "fluid");
    EXPECT_EQ(fluid.line(), 26);
    EXPECT_DOUBLE_EQ(fluid.scalar("density"), 1.1);
    EXPECT_EQ(exponents(fluid.find("density")), (std::vector<double>{1, -3, 0, 0, 0, 0, 0}));
    EXPECT_DOUBLE_EQ(fluid.scalar("nu"), 1e-5);
    EXPECT_EQ(exponents(fluid.find("nu")), (std::vector<double>{0, 2, -1, 0, 0}));
    const Dictionary& deeper = fluid.subDict("inner").subDict("deeper");
    EXPECT_EQ(deeper.path(), "fluid.inner.deeper");
    EXPECT_EQ(deeper.keyPath("value"), "fluid.inner.deeper.value");
    EXPECT_EQ(deeper.line(), 29);
    EXPECT_EQ(deeper.integer("value"), 42);
    EXPECT_TRUE(fluid.isDict("inner"));
    EXPECT_FALSE(fluid.isDict("density"));
    EXPECT_FALSE(top.find("standoff")->dimensions.has_value());
    const auto& entries = fluid.entries();
    EXPECT_EQ(std::count_if(entries.begin(), entries.end(),
                            [](const DictEntry& entry) { return entry.dimensions.has_value(); }),
              2);
}

TEST_F(CaseFile, MacrosOfEveryKind) {
    const Dictionary& carrier = top.subDict("carrier");
    EXPECT_DOUBLE_EQ(carrier.scalar("velocity"), 0.06); // $..name: parent
    EXPECT_DOUBLE_EQ(carrier.scalar("density"), 1.1);   // $a.b: scoped, with its dimensions
    EXPECT_EQ(exponents(carrier.find("density")), (std::vector<double>{1, -3, 0, 0, 0, 0, 0}));
    EXPECT_EQ(carrier.integer("deep"), 42);    // ${a.b.c}
    EXPECT_EQ(carrier.integer("fromTop"), 42); // $:a.b.c
    // key $dictionary; copies the dictionary to the new path
    ASSERT_TRUE(carrier.isDict("copyOfFluid"));
    const Dictionary& copy = carrier.subDict("copyOfFluid");
    EXPECT_EQ(copy.path(), "carrier.copyOfFluid");
    EXPECT_EQ(copy.subDict("inner").subDict("deeper").path(), "carrier.copyOfFluid.inner.deeper");
    EXPECT_DOUBLE_EQ(copy.scalar("density"), 1.1);
    EXPECT_EQ(exponents(copy.find("nu")), (std::vector<double>{0, 2, -1, 0, 0}));

    const Dictionary& coeffs = carrier.subDict("analyticJetCoeffs");
    EXPECT_EQ(coeffs.path(), "carrier.analyticJetCoeffs");
    EXPECT_DOUBLE_EQ(coeffs.scalar("speed"), 0.06); // $..velocity in carrier
    EXPECT_DOUBLE_EQ(coeffs.scalar("again"), 0.06); // $velocity found outwards
    // a standalone $dictionary merges its entries here
    EXPECT_EQ(coeffs.keys(), (std::vector<std::string>{"profile", "speed", "again", "deeper"}));
    EXPECT_EQ(coeffs.subDict("deeper").path(), "carrier.analyticJetCoeffs.deeper");
    EXPECT_EQ(coeffs.subDict("deeper").integer("value"), 42);
}

TEST_F(CaseFile, ListsCountedUniformNestedAndMixed) {
    const Dictionary& lists = top.subDict("lists");
    EXPECT_EQ(lists.vector("point"), Eigen::Vector3d(0.06, 0, -1));
    EXPECT_EQ(lists.find("point")->items.front().list().front().line(), 51); // at the reference
    EXPECT_EQ(lists.scalarList("counted"), (std::vector<double>{1, 2, 3}));
    EXPECT_EQ(lists.scalarList("uniform"), (std::vector<double>{0.5, 0.5, 0.5, 0.5}));
    const auto& nested = lists.find("nested")->items.front().list();
    ASSERT_EQ(nested.size(), 3u);
    EXPECT_EQ(nested[0].list().size(), 2u);
    EXPECT_EQ(nested[1].list().size(), 3u);
    EXPECT_DOUBLE_EQ(nested[1].list()[2].number(), 5);
    EXPECT_TRUE(nested[2].list().empty());
    EXPECT_EQ(lists.wordList("words"), (std::vector<std::string>{"alpha", "beta gamma", "delta"}));
    EXPECT_EQ(lists.scalarList("long"), (std::vector<double>{7, 8}));
    const auto& mixed = lists.find("mixed")->items;
    ASSERT_EQ(mixed.size(), 2u);
    EXPECT_EQ(mixed[0].text(), "uniform");
    EXPECT_EQ(mixed[1].list().size(), 3u);
    // "(0 (1 0 0))" is a number and a list, not a size-prefixed list
    const auto& table = lists.find("table")->items.front().list();
    ASSERT_EQ(table.size(), 2u);
    ASSERT_EQ(table[1].list().size(), 2u);
    EXPECT_DOUBLE_EQ(table[1].list()[0].number(), 1);
    EXPECT_DOUBLE_EQ(table[1].list()[1].list()[0].number(), 2);
}

// ---------------------------------------------------------------------------------------------
// Smaller syntax cases

TEST(DictionarySyntax, NumbersAndTheirIntegerFlag) {
    const Dictionary d = Dictionary::parseString(
        "a 1e-5; b -3; c .5; d -.5; e +2; f 1.; g 2E3; h 0; i 007;", "numbers");
    const std::vector<std::pair<const char*, double>> values{{"a", 1e-5}, {"b", -3}, {"c", 0.5},
                                                             {"d", -0.5}, {"e", 2},  {"f", 1},
                                                             {"g", 2e3},  {"h", 0},  {"i", 7}};
    for (const auto& [key, value] : values) EXPECT_DOUBLE_EQ(d.scalar(key), value) << key;
    for (const char* key : {"b", "e", "h", "i"})
        EXPECT_TRUE(d.find(key)->items.front().writtenAsInteger()) << key;
    for (const char* key : {"a", "c", "d", "f", "g"})
        EXPECT_FALSE(d.find(key)->items.front().writtenAsInteger()) << key;
    EXPECT_EQ(d.integer("g"), 2000); // whole, though written as a float
}

TEST(DictionarySyntax, WordsStringsAndComments) {
    const Dictionary d = Dictionary::parseString("w a.b_c:d-e/f<g>h2;   // comment\n"
                                                 "x a// comment\n"
                                                 ";\n"
                                                 "s \"one\\\ntwo\";\n"
                                                 "/* block\n"
                                                 "   comment */ t \"\\\"q\\\" \\\\ \";\n"
                                                 "u \"plain\";\n",
                                                 "words");
    EXPECT_EQ(d.word("w"), "a.b_c:d-e/f<g>h2");
    EXPECT_EQ(d.word("x"), "a");
    EXPECT_EQ(d.text("s"), "one\ntwo"); // backslash-newline continues the string
    EXPECT_EQ(d.lineOf("t"), 7);
    EXPECT_EQ(d.text("t"), "\"q\" \\\\ ");
    EXPECT_EQ(d.word("u"), "plain"); // a quoted string that is a valid word
    EXPECT_EQ(d.find("u")->items.front().kind(), DictItem::Kind::string);
}

TEST(DictionarySyntax, BooleansAreOpenFoamSwitches) {
    const Dictionary d =
        Dictionary::parseString("a on; b off; c true; d false; e yes; f no;", "switches");
    EXPECT_TRUE(d.boolean("a"));
    EXPECT_FALSE(d.boolean("b"));
    EXPECT_TRUE(d.boolean("c"));
    EXPECT_FALSE(d.boolean("d"));
    EXPECT_TRUE(d.boolean("e"));
    EXPECT_FALSE(d.boolean("f"));
}

TEST(DictionarySyntax, EmptyDictionariesStraySemicolonsAndDictionariesInLists) {
    const Dictionary d = Dictionary::parseString("empty {};\n"
                                                 ";\n"
                                                 "patches ( inlet { type patch; }\n"
                                                 "          outlet { type wall; } );\n",
                                                 "lists");
    EXPECT_TRUE(d.subDict("empty").keys().empty());
    EXPECT_EQ(d.subDict("empty").path(), "empty");
    const auto& patches = d.find("patches")->items.front().list();
    ASSERT_EQ(patches.size(), 4u);
    EXPECT_EQ(patches[2].text(), "outlet");
    EXPECT_EQ(patches[3].dictionary().word("type"), "wall");
    EXPECT_EQ(patches[3].line(), 4);
    EXPECT_EQ(patches[1].dictionary().path(), "patches");
}

TEST(DictionarySyntax, ReferencesSeeOnlyEarlierDefinitions) {
    const Dictionary d = Dictionary::parseString("a 1;\n"
                                                 "b $a;\n"
                                                 "a 2;\n"
                                                 "c ($a $a);\n"
                                                 "d { a 3; e $a; f $.a; g $..a; }\n",
                                                 "order");
    EXPECT_DOUBLE_EQ(d.scalar("b"), 1);
    EXPECT_EQ(d.scalarList("c"), (std::vector<double>{2, 2}));
    EXPECT_DOUBLE_EQ(d.subDict("d").scalar("e"), 3);
    EXPECT_DOUBLE_EQ(d.subDict("d").scalar("f"), 3);
    EXPECT_DOUBLE_EQ(d.subDict("d").scalar("g"), 2);
}

TEST(DictionaryOverwrite, LaterDefinitionReplacesValueInPlaceAndMergesDictionaries) {
    const Dictionary d = Dictionary::parseString("a 1;\n"
                                                 "b { x 1; y 2; }\n"
                                                 "c 3;\n"
                                                 "a 4;\n"
                                                 "b { y 5; z 6; }\n"
                                                 "c { w 1; }\n",
                                                 "overwrite");
    EXPECT_EQ(d.keys(), (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_DOUBLE_EQ(d.scalar("a"), 4);
    EXPECT_EQ(d.lineOf("a"), 4);
    const Dictionary& b = d.subDict("b");
    EXPECT_EQ(b.keys(), (std::vector<std::string>{"x", "y", "z"}));
    EXPECT_DOUBLE_EQ(b.scalar("x"), 1);
    EXPECT_DOUBLE_EQ(b.scalar("y"), 5);
    EXPECT_DOUBLE_EQ(b.scalar("z"), 6);
    EXPECT_TRUE(d.isDict("c"));
    EXPECT_DOUBLE_EQ(d.subDict("c").scalar("w"), 1);
}

// ---------------------------------------------------------------------------------------------
// Syntax errors: each located at file, line and key path

struct ErrorCase {
    const char* name;
    const char* text;
    int line;
    const char* key;
    const char* fragment; ///< expected in what()
};

const ErrorCase syntaxErrors[] = {
    {"MissingSemicolonBeforeClosingBrace",
     "fluid\n"
     "{\n"
     "    density 1.1\n"
     "}\n",
     3, "fluid.density", "missing ';' at the end of the entry (found '}' on line 4)"},
    {"MissingSemicolonBeforeNextDictionary",
     "standoff 0.06\n"
     "fluid\n"
     "{\n"
     "}\n",
     1, "standoff", "missing ';' at the end of the entry ('fluid {' on line 2"},
    {"MissingSemicolonAtEndOfFile",
     "a 1;\n"
     "b (1\n"
     "   2)\n",
     3, "b", "missing ';' at the end of the entry (found the end of the file)"},
    {"KeywordWithoutValue",
     "a 1;\n"
     "b\n",
     2, "b", "missing value and ';' after the keyword"},
    {"UnclosedBrace",
     "particles\n"
     "{\n"
     "    radiusDistribution\n"
     "    {\n"
     "        mean 1e-6;\n"
     "    }\n"
     "count 3;\n",
     2, "particles", "the '{' opened on this line is never closed"},
    {"UnclosedNestedBrace",
     "a\n"
     "{\n"
     "    b\n"
     "    {\n"
     "        c 1;\n",
     4, "a.b", "unexpected end of file"},
    {"UnexpectedClosingBrace",
     "a 1;\n"
     "}\n"
     "b 2;\n",
     2, "", "unexpected '}': no dictionary is open here"},
    {"UnclosedParenthesisBeforeSemicolon",
     "a 1;\n"
     "b\n"
     "(\n"
     "    1 2\n"
     ";\n",
     3, "b", "the '(' opened on this line is not closed with ')' before ';' on line 5"},
    {"UnclosedParenthesisAtEndOfFile",
     "d\n"
     "{\n"
     "    x (1 2\n",
     3, "d.x", "the '(' opened on this line is never closed"},
    {"UnexpectedClosingParenthesis", "a 1 2);\n", 1, "a", "unexpected ')'"},
    {"UnterminatedString",
     "a 1;\n"
     "name \"abc;\n"
     "b 2;\n",
     2, "name", "string is not closed on its line"},
    {"UnterminatedBlockComment",
     "d\n"
     "{\n"
     "    a 1;\n"
     "    /* never closed\n"
     "}\n",
     4, "d", "comment '/*' is never closed with '*/'"},
    {"CountMismatch",
     "p\n"
     "{\n"
     "    r 4(1 2 3);\n"
     "}\n",
     3, "p.r", "the size prefix says 4 but the list has 3 elements"},
    {"UniformListWithTwoValues", "a 3{1 2};\n", 1, "a", "holds exactly one value"},
    {"BadNumber",
     "a\n"
     "{\n"
     "    b 1.2.3;\n"
     "}\n",
     3, "a.b", "bad number '1.2.3'"},
    {"BadNumberWithLetters", "a 3x;\n", 1, "a", "bad number '3x'"},
    {"CommaInList", "a (1, 2);\n", 1, "a", "separated by spaces"},
    {"UnknownReference", "a $b;\n", 1, "a", "unknown reference '$b'"},
    {"ReferenceBeforeDefinition",
     "a $b;\n"
     "b 1;\n",
     1, "a", "no such entry is defined before this point"},
    {"UnknownScopedReference",
     "s { x 1; }\n"
     "t $s.y;\n",
     2, "t", "unknown reference '$s.y'"},
    {"UnknownTopReference",
     "x 1;\n"
     "d\n"
     "{\n"
     "    e { y 1; }\n"
     "    z $:e.y;\n"
     "}\n",
     5, "d.z", "unknown reference '$:e.y'"},
    {"ReferenceAboveTop", "a $..b;\n", 1, "a", "climbs above the top-level dictionary"},
    {"UnclosedBraceReference", "a ${b;\n", 1, "a", "'${' is never closed"},
    {"StandaloneReferenceToValue",
     "a 1;\n"
     "d\n"
     "{\n"
     "    $a;\n"
     "}\n",
     4, "d", "'$a' standing alone merges a dictionary, but it names a value"},
    {"UnsupportedDirective", "#calc \"1 + 2\";\n", 1, "", "unsupported directive '#calc'"},
    {"UnsupportedDirectiveInDictionary",
     "d\n"
     "{\n"
     "    #codeStream\n"
     "    {\n"
     "    };\n"
     "}\n",
     3, "d", "unsupported directive '#codeStream'"},
    {"UnsupportedInputMode", "#inputMode overwrite\n", 1, "", "unsupported directive"},
    {"DirectiveInValue", "a 1;\nb #calc \"$a + 1\";\n", 2, "b", "unsupported directive '#calc'"},
    {"IncludeWithoutQuotes", "#include common\n", 1, "", "#include needs a quoted file name"},
    {"DimensionSetWithThreeExponents", "rho [1 -3 0] 1.1;\n", 1, "rho",
     "a dimension set has 7 exponents [kg m s K mol A cd] (or 5), found 3"},
    {"UnclosedDimensionSet", "rho [1 -3 0 0 0 0 0 1.1;\n", 1, "rho", "never closed with ']'"},
    {"NamedUnits", "rho [kg m^-3] 1.1;\n", 1, "rho", "named units are not supported"},
    {"TwoDimensionSets", "rho [0 0 0 0 0] [0 0 0 0 0] 1;\n", 1, "rho", "two dimension sets"},
    {"DimensionSetInList", "p ([0 1 0 0 0 0 0] 1);\n", 1, "p", "not inside a list"},
    {"QuotedKeyword", "\"(inlet|outlet)\" 1;\n", 1, "", "quoted keywords"},
    {"NumberAsKeyword",
     "a 1;\n"
     "2 3;\n",
     2, "", "expected a keyword, found number 2"},
    {"HeaderNotADictionary", "FoamFile 2.0;\n", 1, "FoamFile", "must be a dictionary"},
};

void PrintTo(const ErrorCase& error, std::ostream* out) { *out << error.name; }

class SyntaxError : public testing::TestWithParam<ErrorCase> {};

TEST_P(SyntaxError, IsLocatedAtFileLineAndKey) {
    const ErrorCase& expected = GetParam();
    const InputError error = parseError(expected.text);
    EXPECT_EQ(error.file(), "case/slidesProperties");
    EXPECT_EQ(error.line(), expected.line) << error.what();
    EXPECT_EQ(error.key(), expected.key) << error.what();
    EXPECT_NE(std::string(error.what()).find(expected.fragment), std::string::npos)
        << "what(): " << error.what() << "\nexpected: " << expected.fragment;
    EXPECT_EQ(std::string(error.what())
                  .rfind("case/slidesProperties:" + std::to_string(expected.line) + ":", 0),
              0u)
        << error.what();
}

INSTANTIATE_TEST_SUITE_P(Dictionary, SyntaxError, testing::ValuesIn(syntaxErrors),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(DictionaryInclude, ErrorInsideIncludedFileNamesThatFile) {
    TemporaryDirectory directory;
    const fs::path included = directory.write("inc", "x 1;\n"
                                                     "y 2\n");
    const fs::path main = directory.write("main", "outer\n"
                                                  "{\n"
                                                  "    #include \"inc\"\n"
                                                  "}\n");
    const InputError error = readError([&] { Dictionary::parseFile(main); });
    EXPECT_EQ(error.file(), included.string());
    EXPECT_EQ(error.line(), 2);
    EXPECT_EQ(error.key(), "outer.y");
    EXPECT_NE(std::string(error.what()).find("missing ';'"), std::string::npos);
}

TEST(DictionaryInclude, MissingIncludedFileIsReportedAtTheDirective) {
    TemporaryDirectory directory;
    const fs::path main = directory.write("main", "a 1;\n"
                                                  "#include \"nowhere/common\"\n");
    const InputError error = readError([&] { Dictionary::parseFile(main); });
    EXPECT_EQ(error.file(), main.string());
    EXPECT_EQ(error.line(), 2);
    EXPECT_NE(std::string(error.what()).find("cannot read included file"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("no such file"), std::string::npos);
}

TEST(DictionaryInclude, DeviceIsRefusedInsteadOfReadForever) {
    // /dev/zero never ends: an #include of it must fail at once, not hang the run.
    TemporaryDirectory directory;
    const fs::path main = directory.write("main", "a 1;\n#include \"/dev/zero\"\n");
    const InputError error = readError([&] { Dictionary::parseFile(main); });
    EXPECT_EQ(error.line(), 2);
    EXPECT_NE(std::string(error.what()).find("not a regular file"), std::string::npos);
}

TEST(DictionaryInclude, RecursiveIncludeIsAnError) {
    TemporaryDirectory directory;
    const fs::path first = directory.write("first", "a 1;\n#include \"second\"\n");
    const fs::path second = directory.write("second", "b 1;\n\n#include \"first\"\n");
    const InputError error = readError([&] { Dictionary::parseFile(first); });
    EXPECT_EQ(error.file(), second.string());
    EXPECT_EQ(error.line(), 3);
    EXPECT_NE(std::string(error.what()).find("recursive #include"), std::string::npos);
}

TEST(DictionaryFile, MissingFileIsAnErrorAtLineZero) {
    const fs::path missing = fs::path("no/such/dir") / "slidesProperties";
    const InputError error = readError([&] { Dictionary::parseFile(missing); });
    EXPECT_EQ(error.file(), missing.string());
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(error.key(), "");
    EXPECT_NE(std::string(error.what()).find("no such file"), std::string::npos);
}

// ---------------------------------------------------------------------------------------------
// Typed reads

const char* typedText = "speed fast;\n"         // 1
                        "count 2.5;\n"          // 2
                        "flag On;\n"            // 3
                        "point (1 2);\n"        // 4
                        "pointWords (1 a 3);\n" // 5
                        "list (1 two 3);\n"     // 6
                        "words (a 1 b);\n"      // 7
                        "pair 1 2;\n"           // 8
                        "sub { x 1; }\n"        // 9
                        "empty;\n"              // 10
                        "spread 1\n"            // 11
                        "next 2;\n"             // 12
                        "big 1e30;\n"           // 13
                        "spaced \"a b\";\n"     // 14
                        "scalarNotList 3;\n";   // 15

struct ReadErrorCase {
    const char* name;
    void (*read)(const Dictionary&);
    int line;
    const char* key;
    const char* fragment;
};

const ReadErrorCase readErrors[] = {
    {"ScalarFromWord", [](const Dictionary& d) { d.scalar("speed"); }, 1, "speed",
     "expected a number, found word 'fast'"},
    {"IntegerFromFraction", [](const Dictionary& d) { d.integer("count"); }, 2, "count",
     "expected a whole number, found number 2.5"},
    {"IntegerOutOfRange", [](const Dictionary& d) { d.integer("big"); }, 13, "big",
     "expected a whole number"},
    {"BooleanIsCaseSensitive", [](const Dictionary& d) { d.boolean("flag"); }, 3, "flag",
     "expected a switch (on/off, true/false, yes/no), found word 'On'"},
    {"VectorOfTwo", [](const Dictionary& d) { d.vector("point"); }, 4, "point",
     "expected a vector (x y z), found a list of 2 values"},
    {"VectorWithWord", [](const Dictionary& d) { d.vector("pointWords"); }, 5, "pointWords",
     "expected a number for the y component of the vector, found word 'a'"},
    {"ScalarListWithWord", [](const Dictionary& d) { d.scalarList("list"); }, 6, "list",
     "element 2 is word 'two'"},
    {"ScalarListFromScalar", [](const Dictionary& d) { d.scalarList("scalarNotList"); }, 15,
     "scalarNotList", "expected a list of numbers ( ... ), found number 3"},
    {"WordListWithNumber", [](const Dictionary& d) { d.wordList("words"); }, 7, "words",
     "element 2 is number 1"},
    {"ScalarFromTwoValues", [](const Dictionary& d) { d.scalar("pair"); }, 8, "pair",
     "expected a number, found 2 values: 1 2"},
    {"ScalarFromDictionary", [](const Dictionary& d) { d.scalar("sub"); }, 9, "sub",
     "expected a number, found a dictionary"},
    {"ScalarFromNothing", [](const Dictionary& d) { d.scalar("empty"); }, 10, "empty",
     "found no value"},
    {"MissingSemicolonHint", [](const Dictionary& d) { d.scalar("spread"); }, 11, "spread",
     "3 values: 1 next 2 (is a ';' missing at the end of line 11?)"},
    {"WordFromStringWithSpace", [](const Dictionary& d) { d.word("spaced"); }, 14, "spaced",
     "expected a word, found string \"a b\""},
    {"SubDictFromValue", [](const Dictionary& d) { d.subDict("speed"); }, 1, "speed",
     "expected a sub-dictionary { ... }, found word 'fast'"},
    {"MissingKey", [](const Dictionary& d) { d.scalar("absent"); }, 0, "absent",
     "missing required key"},
    {"MissingKeyInSubDictionary", [](const Dictionary& d) { d.subDict("sub").scalar("y"); }, 9,
     "sub.y", "missing required key"},
    {"MissingSubDictionary", [](const Dictionary& d) { d.subDict("nothing"); }, 0, "nothing",
     "missing required sub-dictionary"},
    {"FailAtKey", [](const Dictionary& d) { d.fail("speed", "is too fast"); }, 1, "speed",
     "speed': is too fast"},
    {"FailAtAbsentKey", [](const Dictionary& d) { d.subDict("sub").fail("gone", "needed"); }, 9,
     "sub.gone", "needed"},
};

void PrintTo(const ReadErrorCase& error, std::ostream* out) { *out << error.name; }

class ReadError : public testing::TestWithParam<ReadErrorCase> {};

TEST_P(ReadError, SaysWhatWasExpectedAndWhere) {
    const ReadErrorCase& expected = GetParam();
    const Dictionary d = Dictionary::parseString(typedText, "typed");
    const InputError error = readError([&] { expected.read(d); });
    EXPECT_EQ(error.file(), "typed");
    EXPECT_EQ(error.line(), expected.line) << error.what();
    EXPECT_EQ(error.key(), expected.key) << error.what();
    EXPECT_NE(std::string(error.what()).find(expected.fragment), std::string::npos)
        << "what(): " << error.what() << "\nexpected: " << expected.fragment;
}

INSTANTIATE_TEST_SUITE_P(Dictionary, ReadError, testing::ValuesIn(readErrors),
                         [](const auto& info) { return std::string(info.param.name); });

} // namespace
} // namespace slides
