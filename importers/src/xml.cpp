// Strict XML subset parser: well-formedness is checked (matching tags, quoted attributes,
// no duplicate attributes), DTDs are skipped without being interpreted (no entity expansion
// attacks), depth and element counts are bounded.
#include "spt_import/xml.hpp"

#include "text_cursor.hpp"

#include <cctype>
#include <cstring>

namespace spt::xml {

const Attribute* Element::attr(std::string_view n) const {
    for (const auto& a : attributes)
        if (a.name == n) return &a;
    return nullptr;
}

std::string_view Element::local_name() const {
    std::string_view n = name;
    auto p = n.find(':');
    return p == std::string_view::npos ? n : n.substr(p + 1);
}

namespace {

bool is_name_start(unsigned char c) { return std::isalpha(c) || c == '_' || c == ':' || c >= 0x80; }
bool is_name_char(unsigned char c) { return is_name_start(c) || std::isdigit(c) || c == '-' || c == '.'; }

class Parser : text::Cursor<ParseLimits> {
public:
    Parser(std::string_view t, const std::string& src, const ParseLimits& l) : Cursor(t, src, l) {}

    Result<Element> run() {
        if (s_.size() > lim_.max_bytes) return make_error(Code::LimitExceeded, src_ + ": XML document larger than the limit");
        if (s_.size() >= 3 && (unsigned char)s_[0] == 0xEF && (unsigned char)s_[1] == 0xBB && (unsigned char)s_[2] == 0xBF) pos_ = 3;
        if (!misc()) return err_;
        if (pos_ >= s_.size() || s_[pos_] != '<') { fail("expected the root element"); return err_; }
        Element root;
        if (!element(root, 0)) return err_;
        if (!misc()) return err_;
        if (pos_ != s_.size()) { fail("unexpected content after the root element"); return err_; }
        return root;
    }

private:
    void advance(size_t n) {
        for (size_t i = 0; i < n && pos_ < s_.size(); ++i, ++pos_)
            if (s_[pos_] == '\n') ++line_;
    }
    bool starts(std::string_view w) const { return s_.substr(pos_, w.size()) == w; }
    void skip_ws() {
        while (pos_ < s_.size() && (s_[pos_] == ' ' || s_[pos_] == '\t' || s_[pos_] == '\r' || s_[pos_] == '\n')) advance(1);
    }
    // Skips to just after `end`; fails when it is missing.
    bool skip_past(std::string_view end, const char* what) {
        size_t p = s_.find(end, pos_);
        if (p == std::string_view::npos) { advance(s_.size() - pos_); return fail(std::string("unterminated ") + what); }
        advance(p + end.size() - pos_);
        return true;
    }
    // Prolog and epilog: whitespace, comments, processing instructions, DOCTYPE.
    bool misc() {
        for (;;) {
            skip_ws();
            if (starts("<?")) { if (!skip_past("?>", "processing instruction")) return false; }
            else if (starts("<!--")) { if (!skip_past("-->", "comment")) return false; }
            else if (starts("<!DOCTYPE")) {
                // Skip, honouring an internal subset in brackets; its entities are NOT defined.
                int depth = 0;
                while (pos_ < s_.size()) {
                    char c = s_[pos_];
                    advance(1);
                    if (c == '[') ++depth;
                    else if (c == ']') --depth;
                    else if (c == '>' && depth <= 0) break;
                }
                if (pos_ >= s_.size()) return fail("unterminated DOCTYPE");
            } else return true;
        }
    }
    bool name(std::string& out) {
        if (pos_ >= s_.size() || !is_name_start((unsigned char)s_[pos_])) return fail("expected a name");
        size_t b = pos_;
        while (pos_ < s_.size() && is_name_char((unsigned char)s_[pos_])) ++pos_;
        out.assign(s_.substr(b, pos_ - b));
        return true;
    }
    static void put_utf8(std::string& out, uint32_t cp) {
        if (cp < 0x80) out += char(cp);
        else if (cp < 0x800) { out += char(0xC0 | (cp >> 6)); out += char(0x80 | (cp & 63)); }
        else if (cp < 0x10000) { out += char(0xE0 | (cp >> 12)); out += char(0x80 | ((cp >> 6) & 63)); out += char(0x80 | (cp & 63)); }
        else { out += char(0xF0 | (cp >> 18)); out += char(0x80 | ((cp >> 12) & 63)); out += char(0x80 | ((cp >> 6) & 63)); out += char(0x80 | (cp & 63)); }
    }
    // Decodes character data up to (not including) a stop character.
    bool chars(std::string& out, char stop) {
        while (pos_ < s_.size() && s_[pos_] != stop) {
            char c = s_[pos_];
            if (stop != '<' && c == '<') return fail("'<' in attribute value");
            if (c != '&') { out += c; advance(1); continue; }
            size_t semi = s_.find(';', pos_);
            if (semi == std::string_view::npos || semi - pos_ > 12) return fail("bad entity reference");
            std::string_view ent = s_.substr(pos_ + 1, semi - pos_ - 1);
            if (ent == "amp") out += '&';
            else if (ent == "lt") out += '<';
            else if (ent == "gt") out += '>';
            else if (ent == "quot") out += '"';
            else if (ent == "apos") out += '\'';
            else if (ent.size() >= 2 && ent[0] == '#') {
                uint32_t cp = 0;
                bool hex = ent[1] == 'x';
                std::string_view d = ent.substr(hex ? 2 : 1);
                if (d.empty()) return fail("bad character reference");
                for (char h : d) {
                    int v;
                    if (h >= '0' && h <= '9') v = h - '0';
                    else if (hex && h >= 'a' && h <= 'f') v = h - 'a' + 10;
                    else if (hex && h >= 'A' && h <= 'F') v = h - 'A' + 10;
                    else return fail("bad character reference");
                    cp = cp * (hex ? 16 : 10) + uint32_t(v);
                    if (cp > 0x10FFFF) return fail("character reference out of range");
                }
                if (cp == 0 || (cp >= 0xD800 && cp <= 0xDFFF)) return fail("invalid character reference");
                put_utf8(out, cp);
            } else return fail("unknown entity '&" + std::string(ent) + ";' (only the XML predefined entities are supported)");
            advance(semi + 1 - pos_);
        }
        return true;
    }
    bool element(Element& e, uint32_t depth) {
        if (depth > lim_.max_depth) return fail("elements nested deeper than " + std::to_string(lim_.max_depth));
        if (++count_ > lim_.max_elements) return fail("too many XML elements", Code::LimitExceeded);
        e.line = line_;
        advance(1);  // '<'
        if (!name(e.name)) return false;
        for (;;) {
            size_t before = pos_;
            skip_ws();
            if (pos_ >= s_.size()) return fail("unterminated start tag <" + e.name + ">");
            if (s_[pos_] == '/') {
                if (!starts("/>")) return fail("expected '/>'");
                advance(2);
                return true;
            }
            if (s_[pos_] == '>') { advance(1); break; }
            if (pos_ == before) return fail("expected whitespace between attributes of <" + e.name + ">");
            Attribute a;
            a.line = line_;
            if (!name(a.name)) return false;
            skip_ws();
            if (pos_ >= s_.size() || s_[pos_] != '=') return fail("expected '=' after attribute " + a.name);
            advance(1);
            skip_ws();
            if (pos_ >= s_.size() || (s_[pos_] != '"' && s_[pos_] != '\'')) return fail("attribute " + a.name + " value must be quoted");
            char q = s_[pos_];
            advance(1);
            if (!chars(a.value, q)) return false;
            if (pos_ >= s_.size()) return fail("unterminated value of attribute " + a.name);
            advance(1);
            if (e.attr(a.name)) return fail("duplicate attribute " + a.name + " on <" + e.name + ">");
            e.attributes.push_back(std::move(a));
        }
        // Content.
        for (;;) {
            if (pos_ >= s_.size()) return fail("element <" + e.name + "> (line " + std::to_string(e.line) + ") is not closed");
            if (s_[pos_] != '<') { if (!chars(e.text, '<')) return false; continue; }
            if (starts("</")) {
                advance(2);
                std::string n;
                if (!name(n)) return false;
                if (n != e.name) return fail("</" + n + "> closes <" + e.name + "> opened on line " + std::to_string(e.line));
                skip_ws();
                if (pos_ >= s_.size() || s_[pos_] != '>') return fail("expected '>' in end tag");
                advance(1);
                return true;
            }
            if (starts("<!--")) { if (!skip_past("-->", "comment")) return false; continue; }
            if (starts("<?")) { if (!skip_past("?>", "processing instruction")) return false; continue; }
            if (starts("<![CDATA[")) {
                advance(9);
                size_t p = s_.find("]]>", pos_);
                if (p == std::string_view::npos) return fail("unterminated CDATA section");
                e.text.append(s_.substr(pos_, p - pos_));
                advance(p + 3 - pos_);
                continue;
            }
            if (starts("<!")) return fail("unexpected markup declaration inside <" + e.name + ">");
            e.children.emplace_back();
            if (!element(e.children.back(), depth + 1)) return false;
        }
    }
};

}  // namespace

Result<Element> parse(std::string_view text, const std::string& source, const ParseLimits& lim) {
    Parser p(text, source, lim);
    return p.run();
}

std::string escape(std::string_view s) {
    std::string out;
    for (char c : s) {
        switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            case '\'': out += "&apos;"; break;
            default: out += c;
        }
    }
    return out;
}

}  // namespace spt::xml
