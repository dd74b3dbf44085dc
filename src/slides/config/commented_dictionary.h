// CommentedDictionary: writes an OpenFOAM-syntax dictionary of slidesProperties keys, each
// under a comment made from its declaration in the key table (config/scene_keys.h): doc line,
// unit, allowed names and default. A key the table does not declare is a programming error
// (std::logic_error), so a template can never write a key the reader would refuse.
//
//     CommentedDictionary text;
//     text.open("particles");           // // The particles.
//     text.entry("density", "7900");    //     // Particle material density ρp. [kg/m^3]
//     text.close();                     //     density             7900;
#pragma once

#include <sstream>
#include <string>
#include <vector>

namespace slides {

class CommentedDictionary {
public:
    /// Opens the sub-dictionary key of the one open (the top level first), under its comment.
    void open(const std::string& key);
    void close();
    /// `key value;` under its comment, with an optional note after the value.
    void entry(const std::string& key, const std::string& value, const std::string& note = "");
    /// key with its default from the table, under its comment.
    void defaultEntry(const std::string& key);
    /// An optional key, commented out with an example value, under its comment.
    void commentedEntry(const std::string& key, const std::string& example);
    /// A free comment, wrapped.
    void note(const std::string& text);
    /// Text as it is (a banner, a header).
    void raw(const std::string& text);
    std::string text() const { return out_.str(); }

private:
    std::string keyPath(const std::string& key) const;
    /// The declaration's doc line, unit, allowed names and default, as a comment.
    void describe(const std::string& path);
    void wrapped(const std::string& text);
    void line(const std::string& text);

    std::ostringstream out_;
    std::vector<std::string> path_; ///< the open sub-dictionaries
};

} // namespace slides
