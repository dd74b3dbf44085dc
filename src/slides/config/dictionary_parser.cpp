#include "slides/config/dictionary.h"

#include "slides/config/dictionary_lexer.h"
#include "slides/core/error.h"

#include <algorithm>
#include <cerrno>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace slides {

using dictionary_syntax::describe;
using dictionary_syntax::formatNumber;
using dictionary_syntax::Lexer;
using dictionary_syntax::LexFailure;
using dictionary_syntax::Token;

namespace {

constexpr std::size_t maxIncludeDepth = 32;
/// OpenFOAM dictionaries nest a few levels; the parser recurses once per level.
constexpr int maxNesting = 64;
/// A case dictionary is a few kilobytes; these bound the memory a hostile one can take (a value
/// is about 100 bytes in memory), N{value} typos such as 1000000000{0} included.
constexpr std::uintmax_t maxFileBytes = std::uintmax_t{16} << 20;
constexpr std::size_t maxValues = 1'000'000;

/// The file's text, or nothing with the reason in why.
std::optional<std::string> readText(const std::filesystem::path& file, std::string& why) {
    std::error_code error;
    if (!std::filesystem::exists(file, error)) {
        why = error.value() == ELOOP ? "a loop of symbolic links" : "no such file";
        return std::nullopt;
    }
    if (std::filesystem::is_directory(file, error)) {
        why = "it is a directory, not a dictionary file";
        return std::nullopt;
    }
    if (!std::filesystem::is_regular_file(file, error)) {
        // A device or pipe (such as /dev/zero) could be read forever.
        why = "not a regular file (a device, pipe or socket)";
        return std::nullopt;
    }
    if (const auto bytes = std::filesystem::file_size(file, error);
        !error && bytes > maxFileBytes) {
        why = std::to_string(bytes) + " bytes, more than the " + std::to_string(maxFileBytes) +
              " of a case dictionary";
        return std::nullopt;
    }
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        why = "cannot open it (permissions?)";
        return std::nullopt;
    }
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) {
        why = "reading it failed";
        return std::nullopt;
    }
    return text.str();
}

} // namespace

/// Builds dictionaries from tokens. The scope stack holds the dictionaries being built, outermost
/// first, so a $reference sees exactly the entries defined before it.
class DictionaryParser {
public:
    explicit DictionaryParser(Dictionary& top) : top_(top), scopes_{&top} {}

    void parse(std::string_view text) {
        Lexer lexer(text, top_.file());
        parseEntries(lexer, top_, 0);
    }

    void startIncludeChain(const std::filesystem::path& file) {
        std::error_code error;
        includeChain_.push_back(std::filesystem::weakly_canonical(file, error));
    }

private:
    [[noreturn]] static void fail(const Lexer& lexer, int line, const std::string& key,
                                  const std::string& message) {
        throw InputError(lexer.file(), line, key, message);
    }

    static Token take(Lexer& lexer, const std::string& key) {
        try {
            return lexer.take();
        } catch (const LexFailure& failure) {
            fail(lexer, failure.line, key, failure.message);
        }
    }

    static const Token& peek(Lexer& lexer, const std::string& key) {
        try {
            return lexer.peek();
        } catch (const LexFailure& failure) {
            fail(lexer, failure.line, key, failure.message);
        }
    }

    /// Entries until the '}' closing the dictionary opened on openLine, or (openLine 0) until
    /// the end of the file.
    void parseEntries(Lexer& lexer, Dictionary& into, int openLine) {
        const std::string& where = into.path();
        while (true) {
            const Token token = take(lexer, where);
            switch (token.kind) {
            case Token::Kind::end:
                if (openLine > 0)
                    fail(lexer, openLine, where,
                         "unexpected end of file: the '{' opened on this line is never closed "
                         "with '}'");
                return;
            case Token::Kind::word: parseEntry(lexer, into, token, openLine == 0); break;
            case Token::Kind::variable: mergeReferenced(lexer, into, token); break;
            case Token::Kind::directive: directive(lexer, into, token); break;
            case Token::Kind::string:
                fail(lexer, token.line, where,
                     "quoted keywords (OpenFOAM patterns) are not supported; write the keyword "
                     "without quotes");
            case Token::Kind::number:
                fail(lexer, token.line, where, "expected a keyword, found " + describe(token));
            case Token::Kind::punctuation:
                if (token.is('}')) {
                    if (openLine > 0) return;
                    fail(lexer, token.line, where, "unexpected '}': no dictionary is open here");
                }
                if (token.is(';')) break; // OpenFOAM skips stray ';', as in "};"
                fail(lexer, token.line, where, "expected a keyword, found " + describe(token));
            }
        }
    }

    void parseEntry(Lexer& lexer, Dictionary& into, const Token& keyword, bool fileLevel) {
        DictEntry entry;
        entry.keyword = keyword.text;
        entry.line = keyword.line;
        entry.file = lexer.file();
        const std::string key = into.keyPath(keyword.text);
        if (peek(lexer, key).is('{')) {
            entry.dictionary = parseSubDictionary(lexer, take(lexer, key), key);
        } else {
            parseValue(lexer, entry, key);
        }
        if (fileLevel && entry.keyword == "FoamFile") {
            if (!entry.isDict())
                fail(lexer, entry.line, key, "the FoamFile header must be a dictionary { ... }");
            if (includeDepth_ == 0) into.header_ = entry.dictionary;
            return; // headers of included files are dropped, as OpenFOAM does
        }
        addEntry(into, std::move(entry));
    }

    std::shared_ptr<const Dictionary> parseSubDictionary(Lexer& lexer, const Token& open,
                                                         const std::string& path) {
        const Nested nested(*this, lexer, open, path);
        std::shared_ptr<Dictionary> child(new Dictionary(lexer.file(), path, open.line));
        scopes_.push_back(child.get());
        parseEntries(lexer, *child, open.line);
        scopes_.pop_back();
        return child;
    }

    /// One more level of '{' or '(' while it lives; too many end in an InputError, not in a
    /// stack overflow.
    class Nested {
    public:
        Nested(DictionaryParser& parser, const Lexer& lexer, const Token& open,
               const std::string& key)
            : parser_(parser) {
            if (++parser_.nesting_ > maxNesting)
                fail(lexer, open.line, key,
                     "'" + open.text + "' nested more than " + std::to_string(maxNesting) +
                         " deep");
        }
        ~Nested() { --parser_.nesting_; }
        Nested(const Nested&) = delete;
        Nested& operator=(const Nested&) = delete;

    private:
        DictionaryParser& parser_;
    };

    /// Counts values the dictionary will hold; more than maxValues is an InputError.
    void addValues(const Lexer& lexer, int line, const std::string& key, double count) {
        values_ += count;
        if (values_ > static_cast<double>(maxValues))
            fail(lexer, line, key,
                 "more than " + std::to_string(maxValues) + " values in the dictionary");
    }

    static std::size_t valueCount(const DictItem& item) {
        std::size_t count = 1;
        for (const DictItem& element : item.list_) count += valueCount(element);
        if (item.dictionary_) count += valueCount(*item.dictionary_);
        return count;
    }

    static std::size_t valueCount(const Dictionary& dictionary) {
        std::size_t count = 0;
        for (const DictEntry& entry : dictionary.entries_) {
            count += 1;
            for (const DictItem& item : entry.items) count += valueCount(item);
            if (entry.dictionary) count += valueCount(*entry.dictionary);
        }
        return count;
    }

    /// The values of `keyword values... ;` up to and including the ';'.
    void parseValue(Lexer& lexer, DictEntry& entry, const std::string& key) {
        int valueEnd = entry.line;           // line on which the value read so far ends
        int valueEndBeforeLast = entry.line; // ... before the last item
        bool lastIsWord = false;
        while (true) {
            const Token token = take(lexer, key);
            if (token.is(';')) break;
            if (token.kind == Token::Kind::end || token.is('}')) {
                const std::string found = token.kind == Token::Kind::end
                                              ? "the end of the file"
                                              : "'}' on line " + std::to_string(token.line);
                if (entry.items.empty() && !entry.dimensions)
                    fail(lexer, entry.line, key,
                         "missing value and ';' after the keyword (found " + found + ")");
                fail(lexer, valueEnd, key,
                     "missing ';' at the end of the entry (found " + found + ")");
            }
            if (token.is('{')) {
                if (lastIsWord)
                    fail(lexer, valueEndBeforeLast, key,
                         "missing ';' at the end of the entry ('" + entry.items.back().text() +
                             " {' on line " + std::to_string(entry.items.back().line()) +
                             " starts the next one)");
                fail(lexer, token.line, key,
                     "unexpected '{' in a value; a sub-dictionary is written 'keyword { ... }'");
            }
            valueEndBeforeLast = valueEnd;
            if (token.is('[')) {
                if (entry.dimensions)
                    fail(lexer, token.line, key, "the entry has two dimension sets [...]");
                entry.dimensions = parseDimensions(lexer, token, key);
            } else {
                parseItem(lexer, token, entry.items, entry, key, false);
            }
            valueEnd = lexer.lastLine();
            lastIsWord = token.kind == Token::Kind::word;
        }
        // `key $dictionary;` copies the dictionary: the entry becomes a sub-dictionary.
        if (entry.items.size() == 1 && entry.items.front().isDictionary() && !entry.dimensions) {
            entry.dictionary = rebased(entry.items.front().dictionary(), key, entry.line);
            entry.items.clear();
        }
    }

    /// Appends the item(s) that token starts: one value, a list, or a $reference's values.
    void parseItem(Lexer& lexer, const Token& token, std::vector<DictItem>& items, DictEntry& entry,
                   const std::string& key, bool inList) {
        addValues(lexer, token.line, key, 1);
        switch (token.kind) {
        case Token::Kind::number:
            if (token.integer && token.number >= 0) {
                const Token& next = peek(lexer, key);
                // N(...) as OpenFOAM writes short lists, or N then '(' on a new line for long
                if (next.is('(') && (next.glued || next.line > token.line)) {
                    items.push_back(countedList(lexer, token, entry, key));
                    return;
                }
                if (next.is('{') && next.glued) {
                    items.push_back(uniformList(lexer, token, entry, key));
                    return;
                }
            }
            items.push_back(DictItem::makeNumber(token.number, token.integer, token.line));
            return;
        case Token::Kind::word: items.push_back(DictItem::makeWord(token.text, token.line)); return;
        case Token::Kind::string:
            items.push_back(DictItem::makeString(token.text, token.line));
            return;
        case Token::Kind::variable:
            expandReference(lexer, token, items, entry, key, inList);
            return;
        case Token::Kind::directive:
            if (token.text == "#include")
                fail(lexer, token.line, key, "#include must stand where a keyword could");
            unsupportedDirective(lexer, token, key);
        case Token::Kind::punctuation:
            if (token.is('(')) {
                std::vector<DictItem> elements = parseList(lexer, token, entry, key);
                items.push_back(DictItem::makeList(std::move(elements), token.line));
                return;
            }
            if (token.is('{') && inList) {
                items.push_back(
                    DictItem::makeDictionary(parseSubDictionary(lexer, token, key), token.line));
                return;
            }
            if (token.is('['))
                fail(lexer, token.line, key,
                     "a dimension set [...] belongs to the value of an entry, not inside a list");
            fail(lexer, token.line, key, "unexpected " + describe(token));
        case Token::Kind::end: fail(lexer, token.line, key, "unexpected end of file");
        }
    }

    std::vector<DictItem> parseList(Lexer& lexer, const Token& open, DictEntry& entry,
                                    const std::string& key) {
        const Nested nested(*this, lexer, open, key);
        std::vector<DictItem> elements;
        while (true) {
            const Token token = take(lexer, key);
            if (token.is(')')) return elements;
            if (token.kind == Token::Kind::end)
                fail(lexer, open.line, key,
                     "unexpected end of file: the '(' opened on this line is never closed with "
                     "')'");
            if (token.is(';') || token.is('}'))
                fail(lexer, open.line, key,
                     "the '(' opened on this line is not closed with ')' before '" + token.text +
                         "' on line " + std::to_string(token.line));
            if (token.is(']')) fail(lexer, token.line, key, "unexpected ']'");
            parseItem(lexer, token, elements, entry, key, true);
        }
    }

    /// N( ... ): a list whose size is checked against N.
    DictItem countedList(Lexer& lexer, const Token& size, DictEntry& entry,
                         const std::string& key) {
        const Token open = take(lexer, key);
        std::vector<DictItem> elements = parseList(lexer, open, entry, key);
        if (static_cast<double>(elements.size()) != size.number)
            fail(lexer, size.line, key,
                 "list size mismatch: the size prefix says " + formatNumber(size.number) +
                     " but the list has " + std::to_string(elements.size()) + " elements");
        return DictItem::makeList(std::move(elements), size.line);
    }

    /// N{value}: N copies of value.
    DictItem uniformList(Lexer& lexer, const Token& size, DictEntry& entry,
                         const std::string& key) {
        const Token open = take(lexer, key);
        addValues(lexer, size.line, key, size.number);
        std::vector<DictItem> value;
        const Token first = take(lexer, key);
        if (!first.is('}')) parseItem(lexer, first, value, entry, key, true);
        if (value.size() != 1 || !take(lexer, key).is('}'))
            fail(lexer, open.line, key, "a uniform list N{value} holds exactly one value");
        return DictItem::makeList(
            std::vector<DictItem>(static_cast<std::size_t>(size.number), value.front()), size.line);
    }

    DimensionSet parseDimensions(Lexer& lexer, const Token& open, const std::string& key) {
        DimensionSet dimensions;
        while (true) {
            const Token token = take(lexer, key);
            if (token.is(']')) break;
            if (token.kind == Token::Kind::end || token.is(';') || token.is('}'))
                fail(lexer, open.line, key,
                     "the dimension set '[' opened on this line is never closed with ']'");
            if (token.kind != Token::Kind::number)
                fail(lexer, token.line, key,
                     "a dimension set holds exponents [kg m s K mol A cd], found " +
                         describe(token) + " (named units are not supported)");
            dimensions.exponents.push_back(token.number);
        }
        const std::size_t count = dimensions.exponents.size();
        if (count != 7 && count != 5)
            fail(lexer, open.line, key,
                 "a dimension set has 7 exponents [kg m s K mol A cd] (or 5), found " +
                     std::to_string(count));
        return dimensions;
    }

    void expandReference(Lexer& lexer, const Token& reference, std::vector<DictItem>& items,
                         DictEntry& entry, const std::string& key, bool inList) {
        const DictEntry& referenced = resolve(lexer, reference, key);
        addValues(lexer, reference.line, key,
                  static_cast<double>(referenced.isDict() ? valueCount(*referenced.dictionary)
                                                          : valueCount(referenced.items)));
        if (referenced.isDict()) {
            items.push_back(DictItem::makeDictionary(
                rebased(*referenced.dictionary, key, reference.line), reference.line));
            return;
        }
        for (const DictItem& item : referenced.items) {
            items.push_back(item);
            restamp(items.back(), reference.line);
        }
        if (referenced.dimensions && !inList) {
            if (entry.dimensions)
                fail(lexer, reference.line, key,
                     "the entry has two dimension sets [...] (one comes from '$" + reference.text +
                         "')");
            entry.dimensions = referenced.dimensions;
        }
    }

    /// A `$dictionary` standing alone: its entries join the current dictionary.
    void mergeReferenced(Lexer& lexer, Dictionary& into, const Token& reference) {
        const std::shared_ptr<const Dictionary> source =
            resolve(lexer, reference, into.path()).dictionary;
        if (!source)
            fail(lexer, reference.line, into.path(),
                 "'$" + reference.text +
                     "' standing alone merges a dictionary, but it names a value; to copy a "
                     "value write 'keyword $" +
                     reference.text + ";'");
        if (peek(lexer, into.path()).is(';')) take(lexer, into.path());
        addValues(lexer, reference.line, into.path(), static_cast<double>(valueCount(*source)));
        for (DictEntry entry : source->entries_) {
            rebase(entry, into.keyPath(entry.keyword));
            addEntry(into, std::move(entry));
        }
    }

    /// Finds the entry a reference names, among the entries defined before it (OpenFOAM
    /// v1912 scoping: $a searches outwards, $a.b descends, $:a starts at the top, each extra
    /// leading dot of $..a goes one dictionary up).
    const DictEntry& resolve(const Lexer& lexer, const Token& reference, const std::string& key) {
        std::string name = reference.text;
        std::size_t scope = scopes_.size() - 1;
        bool searchOutwards = true;
        if (name.starts_with(':')) {
            scope = 0;
            searchOutwards = false;
            name.erase(0, 1);
        } else if (name.starts_with('.')) {
            const std::size_t dots = name.find_first_not_of('.');
            const std::size_t levelsUp = (dots == std::string::npos ? name.size() : dots) - 1;
            if (levelsUp > scope)
                fail(lexer, reference.line, key,
                     "reference '$" + reference.text + "' climbs above the top-level dictionary");
            scope -= levelsUp;
            searchOutwards = false;
            name.erase(0, levelsUp + 1);
        }
        std::vector<std::string> parts;
        for (std::size_t start = 0;;) {
            const std::size_t dot = name.find('.', start);
            parts.push_back(name.substr(start, dot - start));
            if (dot == std::string::npos) break;
            start = dot + 1;
        }
        for (std::size_t level = scope;; --level) {
            if (const DictEntry* found = findScoped(*scopes_[level], parts, 0)) {
                top_.referencedKeyPaths_.insert(scopes_[level]->keyPath(name));
                return *found;
            }
            if (!searchOutwards || level == 0) break;
        }
        fail(lexer, reference.line, key,
             "unknown reference '$" + reference.text +
                 "': no such entry is defined before this point");
    }

    /// parts[first..] in dictionary: "a.b.c" descends, trying dotted keywords "a.b" as well.
    static const DictEntry* findScoped(const Dictionary& dictionary,
                                       const std::vector<std::string>& parts, std::size_t first) {
        std::string keyword;
        for (std::size_t next = first; next < parts.size(); ++next) {
            keyword += (next == first ? "" : ".") + parts[next];
            const DictEntry* found = dictionary.find(keyword);
            if (!found) continue;
            if (next + 1 == parts.size()) return found;
            if (found->isDict())
                if (const DictEntry* inner = findScoped(*found->dictionary, parts, next + 1))
                    return inner;
        }
        return nullptr;
    }

    void directive(Lexer& lexer, Dictionary& into, const Token& token) {
        if (token.text != "#include") unsupportedDirective(lexer, token, into.path());
        const Token name = take(lexer, into.path());
        if (name.kind != Token::Kind::string)
            fail(lexer, token.line, into.path(),
                 "#include needs a quoted file name, as in #include \"commonSettings\"");
        std::filesystem::path file = name.text;
        if (file.is_relative()) file = std::filesystem::path(lexer.file()).parent_path() / file;
        std::error_code error;
        const auto canonical = std::filesystem::weakly_canonical(file, error);
        if (std::find(includeChain_.begin(), includeChain_.end(), canonical) != includeChain_.end())
            fail(lexer, token.line, into.path(),
                 "recursive #include: '" + file.string() + "' is already being read");
        if (includeDepth_ >= maxIncludeDepth)
            fail(lexer, token.line, into.path(),
                 "#include nested more than " + std::to_string(maxIncludeDepth) + " deep");
        std::string why;
        const std::optional<std::string> text = readText(file, why);
        if (!text)
            fail(lexer, token.line, into.path(),
                 "cannot read included file '" + file.string() + "': " + why);
        Lexer included(*text, file.string());
        includeChain_.push_back(canonical);
        ++includeDepth_;
        parseEntries(included, into, 0);
        --includeDepth_;
        includeChain_.pop_back();
    }

    [[noreturn]] static void unsupportedDirective(const Lexer& lexer, const Token& token,
                                                  const std::string& key) {
        fail(lexer, token.line, key,
             "unsupported directive '" + token.text +
                 "': only #include is supported (no #calc, #codeStream, #includeEtc, "
                 "#inputMode, ...)");
    }

    /// OpenFOAM's default #inputMode merge: a repeated keyword replaces the earlier value in
    /// place; a repeated sub-dictionary is merged into the earlier one.
    static void addEntry(Dictionary& into, DictEntry entry) {
        for (DictEntry& existing : into.entries_) {
            if (existing.keyword != entry.keyword) continue;
            if (existing.isDict() && entry.isDict()) {
                std::shared_ptr<Dictionary> merged(new Dictionary(*existing.dictionary));
                for (const DictEntry& inner : entry.dictionary->entries_) addEntry(*merged, inner);
                existing.dictionary = merged;
            } else {
                existing = std::move(entry);
            }
            return;
        }
        into.entries_.push_back(std::move(entry));
    }

    /// A copy of source placed at another path (its own line becomes the reference's).
    static std::shared_ptr<const Dictionary> rebased(const Dictionary& source,
                                                     const std::string& path, int line) {
        std::shared_ptr<Dictionary> copy(new Dictionary(source));
        copy->path_ = path;
        copy->line_ = line;
        for (DictEntry& entry : copy->entries_) rebase(entry, copy->keyPath(entry.keyword));
        return copy;
    }

    static void rebase(DictEntry& entry, const std::string& path) {
        if (entry.dictionary)
            entry.dictionary = rebased(*entry.dictionary, path, entry.dictionary->line());
        for (DictItem& item : entry.items) rebase(item, path);
    }

    static void rebase(DictItem& item, const std::string& path) {
        if (item.dictionary_) item.dictionary_ = rebased(*item.dictionary_, path, item.line_);
        for (DictItem& element : item.list_) rebase(element, path);
    }

    /// Items copied by a $reference are located at the reference.
    static void restamp(DictItem& item, int line) {
        item.line_ = line;
        for (DictItem& element : item.list_) restamp(element, line);
    }

    static std::size_t valueCount(const std::vector<DictItem>& items) {
        std::size_t count = 0;
        for (const DictItem& item : items) count += valueCount(item);
        return count;
    }

    Dictionary& top_;
    int nesting_ = 0;   ///< '{' and '(' open around the token being read
    double values_ = 0; ///< values read or copied so far
    std::vector<const Dictionary*> scopes_;
    std::vector<std::filesystem::path> includeChain_; ///< files being read, for loop detection
    std::size_t includeDepth_ = 0;
};

Dictionary Dictionary::parseFile(const std::filesystem::path& file) {
    std::string why;
    const std::optional<std::string> text = readText(file, why);
    if (!text) throw InputError(file.string(), 0, "", "cannot read the dictionary: " + why);
    Dictionary top(file.string(), "", 0);
    DictionaryParser parser(top);
    parser.startIncludeChain(file);
    parser.parse(*text);
    return top;
}

Dictionary Dictionary::parseString(std::string_view text, std::string fileName) {
    Dictionary top(std::move(fileName), "", 0);
    DictionaryParser(top).parse(text);
    return top;
}

} // namespace slides
