#include "slides/config/dictionary.h"

#include "slides/config/dictionary_lexer.h"
#include "slides/core/error.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace slides {

using dictionary_syntax::formatNumber;
using dictionary_syntax::isWordCharacter;

namespace {

/// "3 values: 1 b 2" for messages about entries with the wrong number of values.
std::string spellItems(const std::vector<DictItem>& items) {
    if (items.empty()) return "no value";
    std::string spelled = std::to_string(items.size()) + " values:";
    const std::size_t shown = std::min<std::size_t>(items.size(), 6);
    for (std::size_t i = 0; i < shown; ++i) {
        const DictItem& item = items[i];
        spelled += ' ';
        switch (item.kind()) {
        case DictItem::Kind::number: spelled += formatNumber(item.number()); break;
        case DictItem::Kind::word: spelled += item.text(); break;
        case DictItem::Kind::string: spelled += "\"" + item.text() + "\""; break;
        case DictItem::Kind::list: spelled += "(...)"; break;
        case DictItem::Kind::dictionary: spelled += "{...}"; break;
        }
    }
    if (shown < items.size()) spelled += " ...";
    if (items.back().line() != items.front().line())
        spelled +=
            " (is a ';' missing at the end of line " + std::to_string(items.front().line()) + "?)";
    return spelled;
}

std::string describeValue(const DictEntry& entry) {
    if (entry.isDict()) return "a dictionary { ... }";
    if (entry.items.size() == 1) return entry.items.front().describe();
    return spellItems(entry.items);
}

} // namespace

// ----------------------------------------------------------------------------------------------
// DictItem

DictItem DictItem::makeNumber(double value, bool writtenAsInteger, int line) {
    DictItem item(Kind::number, line);
    item.number_ = value;
    item.integer_ = writtenAsInteger;
    return item;
}

DictItem DictItem::makeWord(std::string word, int line) {
    DictItem item(Kind::word, line);
    item.text_ = std::move(word);
    return item;
}

DictItem DictItem::makeString(std::string text, int line) {
    DictItem item(Kind::string, line);
    item.text_ = std::move(text);
    return item;
}

DictItem DictItem::makeList(std::vector<DictItem> elements, int line) {
    DictItem item(Kind::list, line);
    item.list_ = std::move(elements);
    return item;
}

DictItem DictItem::makeDictionary(std::shared_ptr<const Dictionary> dictionary, int line) {
    DictItem item(Kind::dictionary, line);
    item.dictionary_ = std::move(dictionary);
    return item;
}

double DictItem::number() const {
    if (kind_ != Kind::number) throw std::logic_error("DictItem::number() on " + describe());
    return number_;
}

const std::string& DictItem::text() const {
    if (kind_ != Kind::word && kind_ != Kind::string)
        throw std::logic_error("DictItem::text() on " + describe());
    return text_;
}

const std::vector<DictItem>& DictItem::list() const {
    if (kind_ != Kind::list) throw std::logic_error("DictItem::list() on " + describe());
    return list_;
}

const Dictionary& DictItem::dictionary() const {
    if (kind_ != Kind::dictionary)
        throw std::logic_error("DictItem::dictionary() on " + describe());
    return *dictionary_;
}

std::string DictItem::describe() const {
    switch (kind_) {
    case Kind::number: return "number " + formatNumber(number_);
    case Kind::word: return "word '" + text_ + "'";
    case Kind::string: return "string \"" + text_ + "\"";
    case Kind::list: return "a list of " + std::to_string(list_.size()) + " values";
    case Kind::dictionary: return "a dictionary { ... }";
    }
    return "";
}

// ----------------------------------------------------------------------------------------------
// Dictionary

std::string Dictionary::keyPath(std::string_view key) const {
    if (key.empty()) return path_;
    if (path_.empty()) return std::string(key);
    return path_ + "." + std::string(key);
}

bool Dictionary::isReferenced(std::string_view keyPath) const {
    return referencedKeyPaths_.contains(std::string(keyPath));
}

std::vector<std::string> Dictionary::keys() const {
    std::vector<std::string> keys;
    keys.reserve(entries_.size());
    for (const DictEntry& entry : entries_) keys.push_back(entry.keyword);
    return keys;
}

const DictEntry* Dictionary::find(std::string_view key) const {
    for (const DictEntry& entry : entries_)
        if (entry.keyword == key) return &entry;
    return nullptr;
}

int Dictionary::lineOf(std::string_view key) const {
    const DictEntry* entry = find(key);
    return entry ? entry->line : 0;
}

bool Dictionary::isDict(std::string_view key) const {
    const DictEntry* entry = find(key);
    return entry && entry->isDict();
}

const Dictionary& Dictionary::subDict(std::string_view key) const {
    const DictEntry* entry = find(key);
    if (!entry)
        throw InputError(file_, line_, keyPath(key),
                         "missing required sub-dictionary (write '" + std::string(key) +
                             " { ... }')");
    if (!entry->isDict())
        failAt(key, entry->line,
               "expected a sub-dictionary { ... }, found " + describeValue(*entry));
    return *entry->dictionary;
}

void Dictionary::fail(std::string_view key, const std::string& message) const {
    if (const DictEntry* entry = find(key)) failAt(key, entry->line, message);
    throw InputError(file_, line_, keyPath(key), message);
}

void Dictionary::failAt(std::string_view key, int line, const std::string& message) const {
    throw InputError(required(key).file, line, keyPath(key), message);
}

const DictEntry& Dictionary::required(std::string_view key) const {
    const DictEntry* entry = find(key);
    if (!entry) throw InputError(file_, line_, keyPath(key), "missing required key");
    return *entry;
}

const DictItem& Dictionary::singleItem(std::string_view key, const std::string& expected) const {
    const DictEntry& entry = required(key);
    if (entry.isDict() || entry.items.size() != 1)
        failAt(key, entry.line, "expected " + expected + ", found " + describeValue(entry));
    return entry.items.front();
}

double Dictionary::scalar(std::string_view key) const {
    const DictItem& item = singleItem(key, "a number");
    if (!item.isNumber()) failAt(key, item.line(), "expected a number, found " + item.describe());
    return item.number();
}

long Dictionary::integer(std::string_view key) const {
    const DictItem& item = singleItem(key, "a whole number");
    // 2^63: the first double a long cannot hold
    if (!item.isNumber() || item.number() != std::round(item.number()) ||
        std::abs(item.number()) >= 9223372036854775808.0)
        failAt(key, item.line(), "expected a whole number, found " + item.describe());
    return static_cast<long>(item.number());
}

std::string Dictionary::word(std::string_view key) const {
    const DictItem& item = singleItem(key, "a word");
    const bool plainString = item.isString() && !item.text().empty() &&
                             std::all_of(item.text().begin(), item.text().end(), isWordCharacter);
    if (!item.isWord() && !plainString)
        failAt(key, item.line(), "expected a word, found " + item.describe());
    return item.text();
}

std::string Dictionary::text(std::string_view key) const {
    const DictItem& item = singleItem(key, "a word or a quoted string");
    if (!item.isWord() && !item.isString())
        failAt(key, item.line(), "expected a word or a quoted string, found " + item.describe());
    return item.text();
}

bool Dictionary::boolean(std::string_view key) const {
    const std::string expected = "a switch (on/off, true/false, yes/no)";
    const DictItem& item = singleItem(key, expected);
    if (item.isWord()) {
        const std::string& word = item.text();
        if (word == "on" || word == "true" || word == "yes") return true;
        if (word == "off" || word == "false" || word == "no") return false;
    }
    failAt(key, item.line(), "expected " + expected + ", found " + item.describe());
}

Eigen::Vector3d Dictionary::vector(std::string_view key) const {
    const std::string expected = "a vector (x y z)";
    const DictItem& item = singleItem(key, expected);
    if (!item.isList() || item.list().size() != 3)
        failAt(key, item.line(), "expected " + expected + ", found " + item.describe());
    Eigen::Vector3d components;
    for (int axis = 0; axis < 3; ++axis) {
        const DictItem& component = item.list()[static_cast<std::size_t>(axis)];
        if (!component.isNumber())
            failAt(key, component.line(),
                   std::string("expected a number for the ") + "xyz"[axis] +
                       " component of the vector, found " + component.describe());
        components[axis] = component.number();
    }
    return components;
}

std::vector<double> Dictionary::scalarList(std::string_view key) const {
    const DictItem& item = singleItem(key, "a list of numbers ( ... )");
    if (!item.isList())
        failAt(key, item.line(), "expected a list of numbers ( ... ), found " + item.describe());
    std::vector<double> numbers;
    numbers.reserve(item.list().size());
    for (const DictItem& element : item.list()) {
        if (!element.isNumber())
            failAt(key, element.line(),
                   "expected a list of numbers, but element " + std::to_string(numbers.size() + 1) +
                       " is " + element.describe());
        numbers.push_back(element.number());
    }
    return numbers;
}

std::vector<std::string> Dictionary::wordList(std::string_view key) const {
    const DictItem& item = singleItem(key, "a list of words ( ... )");
    if (!item.isList())
        failAt(key, item.line(), "expected a list of words ( ... ), found " + item.describe());
    std::vector<std::string> words;
    words.reserve(item.list().size());
    for (const DictItem& element : item.list()) {
        if (!element.isWord() && !element.isString())
            failAt(key, element.line(),
                   "expected a list of words, but element " + std::to_string(words.size() + 1) +
                       " is " + element.describe());
        words.push_back(element.text());
    }
    return words;
}

} // namespace slides
