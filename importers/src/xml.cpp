// spt::xml on pugixml (see xml.hpp).
#include "spt_import/xml.hpp"

#include <algorithm>
#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <vector>

namespace spt::xml {

namespace {

const char* status_text(pugi::xml_parse_status s) {
    switch (s) {
        case pugi::status_unrecognized_tag: return "unrecognised markup";
        case pugi::status_bad_pi: return "unterminated or malformed processing instruction";
        case pugi::status_bad_comment: return "unterminated or malformed comment";
        case pugi::status_bad_cdata: return "unterminated CDATA section";
        case pugi::status_bad_doctype: return "malformed DOCTYPE";
        case pugi::status_bad_pcdata: return "malformed character data";
        case pugi::status_bad_start_element: return "malformed start tag";
        case pugi::status_bad_attribute: return "malformed attribute (values must be quoted)";
        case pugi::status_bad_end_element: return "malformed end tag";
        case pugi::status_no_document_element: return "no root element";
        default: return nullptr;
    }
}

// An upper bound on the element count: every start tag is '<' and a name character. Lets the
// element limit refuse a document before pugixml allocates a node for each element.
size_t start_tags_at_most(std::string_view t) {
    size_t n = 0;
    for (size_t p = t.find('<'); p != std::string_view::npos; p = t.find('<', p + 1))
        if (p + 1 < t.size() && t[p + 1] != '/' && t[p + 1] != '!' && t[p + 1] != '?') ++n;
    return n;
}

// ' near "<ellips"': the markup where parsing stopped, printable and short.
std::string near(std::string_view t, size_t offset) {
    if (offset >= t.size()) return {};
    const size_t lt = t.rfind('<', offset);
    const size_t b = lt != std::string_view::npos && offset - lt < 24 ? lt : offset;
    std::string s;
    for (size_t i = b; i < t.size() && i < b + 24 && t[i] != '\n'; ++i)
        s += t[i] == 0 ? ' ' : t[i] >= 32 && t[i] < 127 ? t[i] : '?';  // 0: a terminator pugixml wrote
    return " near \"" + s + "\"";
}

}  // namespace

uint32_t Document::line_at(size_t offset) const {
    return uint32_t(1 + (std::lower_bound(newlines_.begin(), newlines_.end(), uint32_t(std::min(offset, text_.size()))) - newlines_.begin()));
}

uint32_t Document::line(pugi::xml_node n) const {
    const ptrdiff_t off = n.offset_debug();  // the name, just after '<'
    return off < 0 ? 0 : line_at(size_t(off));
}

void Document::release(pugi::xml_node n) {
    n.parent().remove_child(n);
#if defined(__GLIBC__)
    // pugixml frees its 32 KiB pages as they empty; glibc keeps freed heap pages mapped unless
    // asked, and the stroke list being built is one large block that cannot reuse them.
    if (++released_ % 65536 == 0) malloc_trim(0);
#endif
}

Result<std::unique_ptr<Document>> Document::parse(std::string text_in, const std::string& source,
                                                  const ParseLimits& lim) {
    if (text_in.size() > lim.max_bytes) return make_error(Code::LimitExceeded, source + ": XML document larger than the limit");
    if (text_in.size() > 0xFFFFFFFFu) return make_error(Code::LimitExceeded, source + ": XML document larger than 4 GiB");
    if (start_tags_at_most(text_in) > lim.max_elements)
        return make_error(Code::LimitExceeded, source + ": too many XML elements (more than " + std::to_string(lim.max_elements) + ")");
    std::unique_ptr<Document> d(new Document());
    d->text_ = std::move(text_in);
    const std::string_view text = d->text_;
    for (size_t p = text.find('\n'); p != std::string_view::npos; p = text.find('\n', p + 1)) d->newlines_.push_back(uint32_t(p));
    d->newlines_.shrink_to_fit();
    auto fail = [&](size_t offset, const std::string& what, Code code = Code::Corrupt) -> Error {
        return make_error(code, source + ":" + std::to_string(d->line_at(offset)) + ": " + what, offset);
    };
    // pugixml's defaults: CDATA kept as text, the predefined entities and character references
    // expanded (only those), line ends normalised; comments and PIs skipped; the DOCTYPE kept
    // as one node, to refuse entity declarations.
    const pugi::xml_parse_result r =
        d->doc_.load_buffer_inplace(d->text_.data(), d->text_.size(), pugi::parse_default | pugi::parse_doctype, pugi::encoding_auto);

    // The limits, over what was parsed (the partial tree too: a deep document is refused for
    // its depth even if it is also unterminated). Iterative: no recursion on hostile depth.
    size_t elements = 0;
    int depth = 0;
    for (pugi::xml_node n = d->doc_.first_child(); n;) {
        if (n.type() == pugi::node_element) {
            if (++elements > lim.max_elements)
                return fail(size_t(n.offset_debug()), "too many XML elements", Code::LimitExceeded);
            if (depth > int(lim.max_depth))
                return fail(size_t(n.offset_debug()), "elements nested deeper than " + std::to_string(lim.max_depth));
            for (pugi::xml_attribute a = n.first_attribute(); a; a = a.next_attribute())
                for (pugi::xml_attribute b = n.first_attribute(); b != a; b = b.next_attribute())
                    if (std::string_view(a.name()) == b.name())
                        return fail(size_t(n.offset_debug()), std::string("duplicate attribute ") + a.name() + " on <" + n.name() + ">");
        }
        if (n.first_child()) {
            n = n.first_child();
            ++depth;
            continue;
        }
        while (n && !n.next_sibling()) {
            n = n.parent();
            --depth;
        }
        if (n) n = n.next_sibling();
    }

    if (!r) {
        if (const char* what = status_text(r.status)) return fail(size_t(r.offset), what + near(text, size_t(r.offset)));
        if (r.status == pugi::status_end_element_mismatch) {
            // pugixml stops on the last byte when the text ends inside an element, else on the
            // name of the end tag that does not match.
            if (size_t(r.offset) + 1 >= text.size()) return fail(size_t(r.offset), "unexpected end of document: an element is not closed");
            size_t e = size_t(r.offset);
            while (e < text.size() && text[e] != '>' && text[e] != ' ' && text[e] != '\n' && text[e] != 0 && e - size_t(r.offset) < 64) ++e;
            return fail(size_t(r.offset), "end tag </" + std::string(text.substr(size_t(r.offset), e - size_t(r.offset))) +
                                              "> does not close the element open here");
        }
        return fail(size_t(r.offset), r.description());
    }
    // Exactly one root element and nothing but markup around it; no entity declarations.
    bool root_seen = false;
    for (pugi::xml_node n = d->doc_.first_child(); n; n = n.next_sibling()) {
        if (n.type() == pugi::node_doctype && std::string_view(n.value()).find("<!ENTITY") != std::string_view::npos)
            return fail(size_t(std::max<ptrdiff_t>(0, n.offset_debug())),
                        "the DOCTYPE declares entities; none is expanded, so the document is refused");
        const bool element = n.type() == pugi::node_element;
        if ((element && root_seen) || n.type() == pugi::node_pcdata || n.type() == pugi::node_cdata)
            return fail(n.offset_debug() < 0 ? 0 : size_t(n.offset_debug()), "unexpected content after the root element");
        root_seen = root_seen || element;
    }
    if (!root_seen) return fail(0, "expected the root element");
    d->elements_ = elements;
    return d;
}

std::string_view local_name(pugi::xml_node n) {
    std::string_view s = n.name();
    const size_t p = s.find(':');
    return p == std::string_view::npos ? s : s.substr(p + 1);
}

}  // namespace spt::xml
