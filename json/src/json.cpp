// spt::json on nlohmann-json: a SAX handler that builds the line-remembering tree and enforces
// spt's limits and rules while nlohmann's lexer and parser check the grammar.
#include "spt_json/json.hpp"
#include "spt_json/write.hpp"

#include <cstdint>
#include <iterator>
#include <memory>
#include <unordered_set>

#include <nlohmann/json.hpp>

namespace spt::json {

const Value* Value::find(std::string_view key) const {
    for (const auto& m : members)
        if (m.first == key) return &m.second;
    return nullptr;
}

const char* type_name(Type t) {
    switch (t) {
        case Type::Null: return "null";
        case Type::Bool: return "boolean";
        case Type::Number: return "number";
        case Type::String: return "string";
        case Type::Array: return "array";
        case Type::Object: return "object";
    }
    return "?";
}

namespace {

// An input iterator over the text that records the last byte nlohmann's lexer has read, so the
// handler knows where each value is (the SAX interface passes no positions).
struct TrackedIterator {
    using iterator_category = std::input_iterator_tag;
    using value_type = char;
    using difference_type = std::ptrdiff_t;
    using pointer = const char*;
    using reference = const char&;
    const char* p = nullptr;
    const char** last = nullptr;
    reference operator*() const { *last = p; return *p; }
    TrackedIterator& operator++() { ++p; return *this; }
    TrackedIterator operator++(int) { TrackedIterator t = *this; ++p; return t; }
    bool operator==(const TrackedIterator& o) const { return p == o.p; }
    bool operator!=(const TrackedIterator& o) const { return p != o.p; }
};

class TreeBuilder {
public:
    using number_integer_t = nlohmann::json::number_integer_t;
    using number_unsigned_t = nlohmann::json::number_unsigned_t;
    using number_float_t = nlohmann::json::number_float_t;
    using string_t = nlohmann::json::string_t;
    using binary_t = nlohmann::json::binary_t;

    TreeBuilder(std::string_view text, const std::string& src, const ParseLimits& lim)
        : text_(text), src_(src), lim_(lim) {}

    const char* last_read = nullptr;  // TrackedIterator's mark
    Value root;
    Error err;

    bool null() { Value* v = add(Type::Null); return v != nullptr; }
    bool boolean(bool b) {
        Value* v = add(Type::Bool);
        if (v) v->boolean = b;
        return v != nullptr;
    }
    bool number_integer(number_integer_t i) { return number(double(i), std::to_string(i)); }
    bool number_unsigned(number_unsigned_t u) { return number(double(u), std::to_string(u)); }
    bool number_float(number_float_t d, const string_t& literal) { return number(d, literal); }
    bool string(string_t& s) {
        Value* v = add(Type::String);
        if (v) v->text = std::move(s);
        return v != nullptr;
    }
    bool binary(binary_t&) { return fail("binary value", Code::Corrupt); }  // not produced by JSON text
    bool start_object(std::size_t) { return open(Type::Object); }
    bool end_object() { open_.pop_back(); return true; }
    bool start_array(std::size_t) { return open(Type::Array); }
    bool end_array() { open_.pop_back(); return true; }
    bool key(string_t& k) {
        Level& l = open_.back();
        auto& members = l.value->members;
        // Duplicate keys are ambiguous. A set only for large objects: most hold a few keys.
        bool dup = false;
        if (!l.keys && members.size() >= 16) {
            l.keys = std::make_unique<std::unordered_set<std::string>>();
            for (const auto& m : members) l.keys->insert(m.first);
        }
        if (l.keys) dup = !l.keys->insert(k).second;
        else for (const auto& m : members) dup = dup || m.first == k;
        if (dup) return fail("duplicate key \"" + k + "\"", Code::Corrupt);
        pending_key_ = std::move(k);
        in_value_ = true;
        return true;
    }
    bool parse_error(std::size_t position, const std::string& last_token, const nlohmann::detail::exception& ex) {
        // nlohmann's message is "[json.exception.parse_error.N] parse error at line L, column C:
        // what"; keep "what", in spt's words where they are established.
        std::string what = ex.what();
        if (size_t c = what.find(": "); c != std::string::npos && what.find("parse error") < c) what = what.substr(c + 2);
        if (size_t l = what.find("; last read: "); l != std::string::npos) what.resize(l);  // raw bytes, maybe many
        if (ex.id == 406) what = "number out of range: " + last_token;
        else if (what.find("unexpected end of input") != std::string::npos) what = "unexpected end of document (" + what + ")";
        else if (values_ > 0 && open_.empty()) what = "unexpected text after the JSON value (" + what + ")";
        else if (what.find("UTF-8") != std::string::npos) what = utf8_context() + " is not valid UTF-8 (" + what + ")";
        const size_t offset = position > 0 ? std::min(position - 1, text_.size()) : 0;
        return fail_at(offset, what, Code::Corrupt);
    }

private:
    struct Level {
        Value* value;
        std::unique_ptr<std::unordered_set<std::string>> keys;
        size_t max_items = SIZE_MAX;  // an array's cap (ParseLimits::max_items_by_key)
    };
    std::string_view text_;
    const std::string& src_;
    ParseLimits lim_;
    std::vector<Level> open_;
    std::string pending_key_;
    bool in_value_ = false;  // after a key, before its value
    size_t values_ = 0;
    size_t scanned_ = 0;  // lines counted up to here
    uint32_t line_ = 1;

    // The offset of the byte the lexer read last (for a number, the one after it).
    size_t here() const { return last_read ? size_t(last_read - text_.data()) : 0; }
    uint32_t line_at(size_t offset) {
        if (offset < scanned_) { scanned_ = 0; line_ = 1; }
        for (; scanned_ < offset && scanned_ < text_.size(); ++scanned_) line_ += text_[scanned_] == '\n';
        return line_;
    }
    bool fail_at(size_t offset, const std::string& what, Code code) {
        const uint32_t line = line_at(offset);
        size_t bol = offset;
        while (bol > 0 && text_[bol - 1] != '\n') --bol;
        err = make_error(code, src_ + ":" + std::to_string(line) + ":" + std::to_string(offset - bol + 1) + ": " + what, offset);
        return false;
    }
    bool fail(const std::string& what, Code code) { return fail_at(here(), what, code); }

    // The name of the open container at `depth` (JSON text is UTF-8: the first place a text may
    // not be is named by its key, as users wrote it).
    std::string name_of(size_t depth) const {
        if (depth == 0) return "the document";
        const Value* parent = open_[depth - 1].value;
        if (parent->type == Type::Object) return "\"" + parent->members.back().first + "\"";
        return name_of(depth - 1) + "[" + std::to_string(parent->items.size() - 1) + "]";
    }
    // What the lexer was reading when it met a byte that is not UTF-8: a key's value, a key, an
    // array item or the document.
    std::string utf8_context() const {
        if (open_.empty()) return "the document";
        const Value* here = open_.back().value;
        const std::string in = open_.size() > 1 ? " in " + name_of(open_.size() - 1) : "";
        if (here->type == Type::Object)
            return in_value_ ? "the value of key \"" + pending_key_ + "\"" + in : "a key of " + name_of(open_.size() - 1);
        return "an item of " + name_of(open_.size() - 1);
    }

    // A new value in the open container (or the root), on the line where its token lies: no
    // token spans a line, and the byte read last is the token's own or, after a number, the
    // one following it (excluded here).
    Value* add(Type t) {
        if (++values_ > lim_.max_values) { fail("too many JSON values", Code::LimitExceeded); return nullptr; }
        Value* v;
        if (open_.empty()) {
            v = &root;
        } else if (open_.back().value->type == Type::Array) {
            if (open_.back().value->items.size() >= open_.back().max_items) {
                fail(name_of(open_.size() - 1) + " holds more than " + std::to_string(open_.back().max_items) + " items",
                     Code::LimitExceeded);
                return nullptr;
            }
            v = &open_.back().value->items.emplace_back();
        } else {
            v = &open_.back().value->members.emplace_back(std::move(pending_key_), Value()).second;
            in_value_ = false;
        }
        v->type = t;
        v->line = line_at(here());
        return v;
    }
    bool number(double d, std::string literal) {
        Value* v = add(Type::Number);
        if (!v) return false;
        v->number = d;
        v->text = std::move(literal);
        return true;
    }
    // A container stays where it is while open: its parent grows only after it is closed.
    bool open(Type t) {
        if (open_.size() > lim_.max_depth) return fail("nesting deeper than " + std::to_string(lim_.max_depth), Code::Corrupt);
        Value* v = add(t);
        if (!v) return false;
        size_t cap = SIZE_MAX;
        if (t == Type::Array && !open_.empty()) {
            const Value* parent = open_.back().value;
            if (parent->type == Type::Array && lim_.max_tuple_items) cap = lim_.max_tuple_items;
            if (parent->type == Type::Object)
                for (const auto& [key, n] : lim_.max_items_by_key)
                    if (parent->members.back().first == key) cap = n;
        }
        open_.push_back({v, nullptr, cap});
        return true;
    }
};

}  // namespace

Result<Value> parse(std::string_view text, const std::string& source, const ParseLimits& lim) {
    if (text.size() > lim.max_bytes)
        return make_error(Code::LimitExceeded, source + ": JSON document larger than the limit");
    TreeBuilder b(text, source, lim);
    TrackedIterator first{text.data(), &b.last_read}, last{text.data() + text.size(), &b.last_read};
    if (!nlohmann::json::sax_parse(first, last, &b, nlohmann::json::input_format_t::json, true)) return b.err;
    return std::move(b.root);
}

std::string quote(std::string_view s) { return dump(Doc(std::string(s))); }

void append_string(std::string& out, std::string_view s) { out += quote(s); }

}  // namespace spt::json
