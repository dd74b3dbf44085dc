// The tokens of OpenFOAM dictionary text and the lexer that splits text into them.
//
// Reference: OpenFOAM v1912 dictionary syntax (OpenFOAM User Guide, "Input/output file format"):
// words, numbers, "strings", $references, #directives, the punctuation { } ( ) [ ] ; and the
// comments // and /* */, which the lexer skips.
//
//     radius 2.5e-3;   // word 'radius', number 0.0025, ';' (this comment is skipped)
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

namespace slides::dictionary_syntax {

/// The shortest text that reads back as value, e.g. "0.1" or "1e-06".
std::string formatNumber(double value);

/// Whether c can be part of a word: any byte but white space, control characters and the
/// delimiters "';{}()[], (bytes of UTF-8 characters included).
bool isWordCharacter(char c);

struct Token {
    enum class Kind { word, number, string, variable, directive, punctuation, end };
    Kind kind = Kind::end;
    std::string text; ///< word, string content, reference name without '$', "#name", or "{"
    int line = 0;
    double number = 0;
    bool integer = false;
    bool glued = false; ///< no space or comment between this token and the previous one

    bool is(char punctuation) const {
        return kind == Kind::punctuation && text.size() == 1 && text[0] == punctuation;
    }
};

/// For messages: "word 'fast'", "number 2.5", "'}'", "end of file", ...
std::string describe(const Token& token);

/// A lexical error; the parser adds the file and the key it was reading.
struct LexFailure {
    int line;
    std::string message;
};

/// Splits OpenFOAM dictionary text into tokens on demand, skipping comments.
class Lexer {
public:
    Lexer(std::string_view text, std::string file) : text_(text), file_(std::move(file)) {}

    const std::string& file() const { return file_; }
    /// Line of the most recently taken token.
    int lastLine() const { return lastLine_; }

    /// The next token, left to be taken. Throws LexFailure.
    const Token& peek();
    /// The next token. Throws LexFailure.
    Token take();

private:
    char at(std::size_t position) const { return position < text_.size() ? text_[position] : '\0'; }

    bool startsComment(std::size_t position) const {
        return at(position) == '/' && (at(position + 1) == '/' || at(position + 1) == '*');
    }

    std::size_t endOfWord(std::size_t position) const;
    void skipSpaceAndComments();
    Token lex();
    bool startsNumber() const;
    void lexNumber(Token& token);
    /// "..." with OpenFOAM's escapes: \" is a quote, a backslash before a newline continues.
    void lexString(Token& token);
    /// $name, $a.b, $:a.b, $..a, ${a.b}.
    void lexReference(Token& token);

    std::string_view text_;
    std::string file_;
    std::size_t position_ = 0;
    int line_ = 1;
    int lastLine_ = 1;
    std::optional<Token> peeked_;
};

} // namespace slides::dictionary_syntax
