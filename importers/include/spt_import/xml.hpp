// SVG's XML: pugixml under the importers' rules, parsed in place (the text is the document's
// storage; pugixml adds its nodes, about 64 bytes an element and 40 an attribute). pugixml processes no DTD (a DOCTYPE is skipped,
// its entities are not defined), expands only the five predefined entities and character
// references, and fetches nothing. On top: a size limit before parsing, a bound on the element
// count before parsing (from the markup itself), depth and element-count limits, duplicate
// attributes refused, one root element, and errors that name the file and the line (computed
// from pugixml's byte offsets only when a message needs one).
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <pugixml.hpp>

#include "spt/result.hpp"

namespace spt::xml {

struct ParseLimits {
    size_t max_bytes = size_t(1) << 30;
    uint32_t max_depth = 256;
    size_t max_elements = size_t(1) << 24;
};

class Document {
public:
    // Parses `text`, which the Document keeps and pugixml rewrites in place. Errors name
    // `source` and the line.
    static Result<std::unique_ptr<Document>> parse(std::string text, const std::string& source,
                                                   const ParseLimits& lim = {});
    pugi::xml_node root() const { return doc_.document_element(); }
    // The 1-based line of an element's '<'.
    uint32_t line(pugi::xml_node n) const;
    // Elements in the document (all of them, at any depth).
    size_t elements() const { return elements_; }
    // Frees an element that has been read, with its subtree: a reader that releases what it
    // has converted holds the nodes of what is left, not of the whole document.
    void release(pugi::xml_node n);

private:
    Document() = default;
    uint32_t line_at(size_t offset) const;
    std::string text_;
    std::vector<uint32_t> newlines_;  // their offsets: the in-place parse overwrites some
    pugi::xml_document doc_;
    size_t elements_ = 0, released_ = 0;
};

// Name without a namespace prefix ("svg:rect" -> "rect").
std::string_view local_name(pugi::xml_node n);

}  // namespace spt::xml
