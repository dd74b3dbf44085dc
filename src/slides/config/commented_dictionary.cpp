#include "slides/config/commented_dictionary.h"

#include "slides/config/scene_keys.h"

#include <algorithm>
#include <stdexcept>

namespace slides {

namespace {

constexpr std::size_t lineWidth = 96; // as the shipped cases' dictionaries
constexpr std::size_t indentWidth = 4;

const KeyDeclaration& declaration(const std::string& path) {
    const KeyDeclaration* key = findSceneKey(path);
    if (!key) throw std::logic_error("commented dictionary: key '" + path + "' is not declared");
    return *key;
}

} // namespace

void CommentedDictionary::open(const std::string& key) {
    describe(keyPath(key));
    line(key);
    line("{");
    path_.push_back(key);
}

void CommentedDictionary::close() {
    path_.pop_back();
    line("}");
    if (path_.empty()) out_ << "\n";
}

void CommentedDictionary::entry(const std::string& key, const std::string& value,
                                const std::string& note) {
    describe(keyPath(key));
    std::string text = key;
    text.resize(std::max<std::size_t>(text.size() + 1, 20), ' ');
    text += value + ";";
    if (!note.empty()) text += "  // " + note;
    line(text);
}

void CommentedDictionary::defaultEntry(const std::string& key) {
    entry(key, declaration(keyPath(key)).fallback);
}

void CommentedDictionary::commentedEntry(const std::string& key, const std::string& example) {
    describe(keyPath(key));
    line("// " + key + " " + example + ";");
}

void CommentedDictionary::note(const std::string& text) { wrapped(text); }

void CommentedDictionary::raw(const std::string& text) { out_ << text; }

std::string CommentedDictionary::keyPath(const std::string& key) const {
    std::string path;
    for (const auto& name : path_) path += name + ".";
    return path + key;
}

void CommentedDictionary::describe(const std::string& path) {
    const KeyDeclaration& key = declaration(path);
    std::string text = key.doc;
    if (key.unit != "-") text += " [" + key.unit + "]";
    if (!key.allowed.empty()) {
        text += " One of:";
        for (const auto& name : key.allowed) text += " " + name;
        text += ".";
    }
    if (!key.required() && !key.optional() && key.kind != KeyKind::dictionary)
        text += " Default: " + key.fallback + ".";
    wrapped(text);
}

void CommentedDictionary::wrapped(const std::string& text) {
    const std::string prefix = "// ";
    const std::size_t width = lineWidth - indentWidth * path_.size() - prefix.size();
    std::istringstream words(text);
    std::string word, current;
    while (words >> word) {
        if (!current.empty() && current.size() + 1 + word.size() > width) {
            line(prefix + current);
            current.clear();
        }
        current += (current.empty() ? "" : " ") + word;
    }
    if (!current.empty()) line(prefix + current);
}

void CommentedDictionary::line(const std::string& text) {
    out_ << std::string(indentWidth * path_.size(), ' ') << text << "\n";
}

} // namespace slides
