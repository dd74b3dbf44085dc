#include "slides/config/dictionary_lexer.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>

namespace slides::dictionary_syntax {

namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

} // namespace

std::string formatNumber(double value) {
    std::array<char, 32> buffer{};
    const auto result = std::to_chars(buffer.data(), buffer.data() + buffer.size(), value);
    return std::string(buffer.data(), result.ptr);
}

bool isWordCharacter(char c) {
    const auto code = static_cast<unsigned char>(c);
    if (code >= 0x80) return true; // UTF-8, e.g. in "ε"
    if (code <= ' ' || code == 0x7f) return false;
    return std::string_view("\"';{}()[],").find(c) == std::string_view::npos;
}

std::string describe(const Token& token) {
    switch (token.kind) {
    case Token::Kind::word: return "word '" + token.text + "'";
    case Token::Kind::number: return "number " + formatNumber(token.number);
    case Token::Kind::string: return "string \"" + token.text + "\"";
    case Token::Kind::variable: return "reference '$" + token.text + "'";
    case Token::Kind::directive: return "directive '" + token.text + "'";
    case Token::Kind::punctuation: return "'" + token.text + "'";
    case Token::Kind::end: return "end of file";
    }
    return token.text;
}

const Token& Lexer::peek() {
    if (!peeked_) peeked_ = lex();
    return *peeked_;
}

Token Lexer::take() {
    Token token = peeked_ ? std::move(*peeked_) : lex();
    peeked_.reset();
    lastLine_ = token.line;
    return token;
}

std::size_t Lexer::endOfWord(std::size_t position) const {
    while (position < text_.size() && isWordCharacter(text_[position]) && !startsComment(position))
        ++position;
    return position;
}

void Lexer::skipSpaceAndComments() {
    while (position_ < text_.size()) {
        const char c = text_[position_];
        if (c == '\n') {
            ++line_;
            ++position_;
        } else if (std::isspace(static_cast<unsigned char>(c))) {
            ++position_;
        } else if (c == '/' && at(position_ + 1) == '/') {
            while (position_ < text_.size() && text_[position_] != '\n') ++position_;
        } else if (c == '/' && at(position_ + 1) == '*') {
            const std::size_t close = text_.find("*/", position_ + 2);
            if (close == std::string_view::npos)
                throw LexFailure{line_, "comment '/*' is never closed with '*/'"};
            line_ += static_cast<int>(
                std::count(text_.begin() + position_, text_.begin() + close, '\n'));
            position_ = close + 2;
        } else {
            return;
        }
    }
}

Token Lexer::lex() {
    const std::size_t before = position_;
    skipSpaceAndComments();
    Token token;
    token.line = line_;
    token.glued = position_ == before;
    if (position_ >= text_.size()) return token;
    const char c = text_[position_];
    if (std::string_view("{}()[];").find(c) != std::string_view::npos) {
        token.kind = Token::Kind::punctuation;
        token.text = std::string(1, c);
        ++position_;
    } else if (c == '"') {
        lexString(token);
    } else if (c == '$') {
        lexReference(token);
    } else if (c == '#') {
        token.kind = Token::Kind::directive;
        ++position_;
        const std::size_t end = at(position_) == '{' ? position_ + 1 : endOfWord(position_);
        token.text = '#';
        token.text += text_.substr(position_, end - position_);
        position_ = end;
    } else if (startsNumber()) {
        lexNumber(token);
    } else if (isWordCharacter(c)) {
        token.kind = Token::Kind::word;
        const std::size_t end = endOfWord(position_);
        token.text = std::string(text_.substr(position_, end - position_));
        position_ = end;
    } else if (c == ',') {
        throw LexFailure{line_, "unexpected ','; OpenFOAM list items are separated by "
                                "spaces, as in (1 2 3)"};
    } else {
        throw LexFailure{line_, "unexpected character '" + std::string(1, c) + "'"};
    }
    return token;
}

bool Lexer::startsNumber() const {
    const char c = at(position_);
    const char next = at(position_ + 1);
    if (isDigit(c)) return true;
    if (c == '.') return isDigit(next);
    if (c == '-' || c == '+') return isDigit(next) || (next == '.' && isDigit(at(position_ + 2)));
    return false;
}

void Lexer::lexNumber(Token& token) {
    const std::size_t end = endOfWord(position_);
    token.kind = Token::Kind::number;
    token.text = std::string(text_.substr(position_, end - position_));
    position_ = end;
    const char* first = token.text.data();
    const char* last = first + token.text.size();
    if (*first == '+') ++first;
    const auto [stop, error] = std::from_chars(first, last, token.number);
    if (error == std::errc::result_out_of_range)
        throw LexFailure{line_, "number '" + token.text + "' is out of range"};
    if (error != std::errc() || stop != last)
        throw LexFailure{line_, "bad number '" + token.text + "'"};
    token.integer = std::all_of(first + (*first == '-' ? 1 : 0), last, isDigit);
}

void Lexer::lexString(Token& token) {
    token.kind = Token::Kind::string;
    const int opened = line_;
    ++position_;
    while (true) {
        if (position_ >= text_.size())
            throw LexFailure{opened, "string is never closed: missing '\"'"};
        const char c = text_[position_++];
        if (c == '"') return;
        if (c == '\n') throw LexFailure{opened, "string is not closed on its line: missing '\"'"};
        if (c == '\\' && (at(position_) == '"' || at(position_) == '\\' || at(position_) == '\n')) {
            const char escaped = text_[position_++];
            if (escaped == '\\') token.text += '\\';
            if (escaped == '\n') ++line_;
            token.text += escaped;
            continue;
        }
        token.text += c;
    }
}

void Lexer::lexReference(Token& token) {
    token.kind = Token::Kind::variable;
    ++position_;
    if (at(position_) == '{') {
        const std::size_t close = text_.find_first_of("}\n", position_);
        if (close == std::string_view::npos || text_[close] != '}')
            throw LexFailure{line_, "reference '${' is never closed with '}'"};
        token.text = std::string(text_.substr(position_ + 1, close - position_ - 1));
        position_ = close + 1;
    } else {
        const std::size_t end = endOfWord(position_);
        token.text = std::string(text_.substr(position_, end - position_));
        position_ = end;
    }
    if (token.text.empty() || std::any_of(token.text.begin(), token.text.end(),
                                          [](char c) { return !isWordCharacter(c); }))
        throw LexFailure{line_, "'$' must be followed by the name of an entry, as in "
                                "$name, $a.b, $:a.b, $..a or ${a.b}"};
}

} // namespace slides::dictionary_syntax
