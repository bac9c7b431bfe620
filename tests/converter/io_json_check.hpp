// JSON checks for tests: tool output must be exactly one valid JSON value (the importers' strict
// RFC 8259 parser, spt_import/json.hpp), looked up through a small map-based tree.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "spt_json/json.hpp"

namespace spt_test {

struct Json {
    enum Type { Null, Bool, Number, String, Array, Object } type = Null;
    bool b = false;
    double num = 0;
    std::string str;
    std::vector<Json> arr;
    std::map<std::string, Json> obj;

    bool has(const std::string& k) const { return type == Object && obj.count(k) > 0; }
    const Json& operator[](const std::string& k) const {
        static const Json null_value;
        auto it = obj.find(k);
        return it == obj.end() ? null_value : it->second;
    }
    const Json& operator[](size_t i) const { return arr.at(i); }
};

class JsonParser {
public:
    // Parses the whole text; false (with `error` set) when it is not exactly one JSON value.
    static bool parse(const std::string& text, Json& out, std::string* error = nullptr) {
        // The shared parser tolerates a byte order mark in input files; tool output must have none.
        if (text.compare(0, 3, "\xEF\xBB\xBF") == 0) {
            if (error) *error = "byte order mark in tool output";
            return false;
        }
        auto v = spt::json::parse(text, "json");
        if (!v) {
            if (error) *error = v.error().message + " (offset " + std::to_string(v.error().offset) + ")";
            return false;
        }
        out = convert(*v);
        return true;
    }

private:
    static Json convert(const spt::json::Value& v) {
        Json j;
        switch (v.type) {
            case spt::json::Type::Null: j.type = Json::Null; break;
            case spt::json::Type::Bool: j.type = Json::Bool; j.b = v.boolean; break;
            case spt::json::Type::Number: j.type = Json::Number; j.num = v.number; break;
            case spt::json::Type::String: j.type = Json::String; j.str = v.text; break;
            case spt::json::Type::Array:
                j.type = Json::Array;
                for (const auto& item : v.items) j.arr.push_back(convert(item));
                break;
            case spt::json::Type::Object:
                j.type = Json::Object;
                for (const auto& m : v.members) j.obj.emplace(m.first, convert(m.second));
                break;
        }
        return j;
    }
};

}  // namespace spt_test
