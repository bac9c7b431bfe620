// A small, strict XML reader for SVG: elements, attributes and line numbers. Text content is
// kept (for <style> and <title>), comments, processing instructions, DOCTYPE and CDATA are
// skipped or kept as text. No external entities, no DTD processing: only the five predefined
// entities and numeric character references are expanded.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "spt/result.hpp"

namespace spt::xml {

struct Attribute {
    std::string name, value;
    uint32_t line = 0;
};

struct Element {
    std::string name;   // qualified name as written ("svg", "xlink:href" stays in attributes)
    uint32_t line = 0;  // line of the '<'
    std::vector<Attribute> attributes;
    std::vector<Element> children;
    std::string text;   // concatenated character data directly inside this element
    const Attribute* attr(std::string_view n) const;
    // Name without a namespace prefix ("svg:rect" -> "rect").
    std::string_view local_name() const;
};

struct ParseLimits {
    size_t max_bytes = size_t(1) << 30;
    uint32_t max_depth = 256;
    size_t max_elements = size_t(1) << 24;
};

// Parses a document and returns its root element. Errors name `source` and the line.
Result<Element> parse(std::string_view text, const std::string& source, const ParseLimits& lim = {});

// Escapes text for an attribute value or character data.
std::string escape(std::string_view s);

}  // namespace spt::xml
