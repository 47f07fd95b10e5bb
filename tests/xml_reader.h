#pragma once
// A strict reader for the XML subset JUnit files use, for tests that check a written file is
// well-formed without an XML library: a declaration, elements, double-quoted attributes, text and
// the five predefined entities. Anything else (comments, CDATA, DOCTYPE) counts as malformed.
#include <cctype>
#include <map>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace testutil {

/// An element with its attributes (entities decoded), children and text (all its text pieces joined).
struct XmlElement {
    std::string name;
    std::map<std::string, std::string> attributes;
    std::vector<XmlElement> children;
    std::string text;
    /// Elements named `tag` in this subtree, this one included.
    [[nodiscard]] size_t count(const std::string& tag) const {
        size_t n = name == tag;
        for (const auto& c : children) n += c.count(tag);
        return n;
    }
};

/// XmlReader(text).document() parses the whole text; throws std::runtime_error when malformed.
class XmlReader {
public:
    explicit XmlReader(std::string_view text) : s_(text) {}
    XmlElement document() {
        if (s_.starts_with("<?xml")) {
            const size_t end = s_.find("?>");
            if (end == std::string_view::npos) fail("unterminated declaration");
            i_ = end + 2;
        }
        skipSpace();
        XmlElement root = element();
        skipSpace();
        if (i_ != s_.size()) fail("content after the root element");
        return root;
    }

private:
    [[noreturn]] void fail(const std::string& why) const {
        throw std::runtime_error("XML: " + why + " at " + std::to_string(i_));
    }
    void skipSpace() {
        while (i_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[i_]))) ++i_;
    }
    void expect(char c) {
        if (i_ >= s_.size() || s_[i_] != c) fail(std::string("expected '") + c + "'");
        ++i_;
    }
    std::string name() {
        const size_t start = i_;
        while (i_ < s_.size() && (std::isalnum(static_cast<unsigned char>(s_[i_])) || s_[i_] == '_' || s_[i_] == '-' ||
                                  s_[i_] == ':' || s_[i_] == '.'))
            ++i_;
        if (i_ == start) fail("expected a name");
        return std::string(s_.substr(start, i_ - start));
    }
    std::string decode(std::string_view raw) const {
        static const std::map<std::string, char> entities = {
            {"amp", '&'}, {"lt", '<'}, {"gt", '>'}, {"quot", '"'}, {"apos", '\''}};
        std::string out;
        for (size_t k = 0; k < raw.size(); ++k) {
            if (raw[k] == '<') fail("raw '<' in text");
            if (raw[k] != '&') {
                out += raw[k];
                continue;
            }
            const size_t semi = raw.find(';', k);
            const auto it =
                semi == raw.npos ? entities.end() : entities.find(std::string(raw.substr(k + 1, semi - k - 1)));
            if (it == entities.end()) fail("unknown or unterminated entity");
            out += it->second;
            k = semi;
        }
        return out;
    }
    XmlElement element() {
        expect('<');
        XmlElement e;
        e.name = name();
        for (;;) {
            skipSpace();
            if (s_.substr(i_).starts_with("/>")) {
                i_ += 2;
                return e;
            }
            if (i_ < s_.size() && s_[i_] == '>') {
                ++i_;
                break;
            }
            const std::string key = name();
            expect('=');
            expect('"');
            const size_t end = s_.find('"', i_);
            if (end == std::string_view::npos) fail("unterminated attribute");
            if (!e.attributes.emplace(key, decode(s_.substr(i_, end - i_))).second) fail("duplicate attribute " + key);
            i_ = end + 1;
        }
        for (;;) {
            if (i_ >= s_.size()) fail("unclosed <" + e.name + ">");
            if (s_.substr(i_).starts_with("</")) {
                i_ += 2;
                if (name() != e.name) fail("mismatched end tag of <" + e.name + ">");
                skipSpace();
                expect('>');
                return e;
            }
            if (s_[i_] == '<') {
                e.children.push_back(element());
                continue;
            }
            const size_t end = s_.find('<', i_);
            e.text += decode(s_.substr(i_, end - i_));
            i_ = end == std::string_view::npos ? s_.size() : end;
        }
    }
    std::string_view s_;
    size_t i_ = 0;
};

} // namespace testutil
