// The option table as JSON (spt paint --options-json): what a front end needs to offer the
// options without keeping a list of its own.
#include <nlohmann/json.hpp>

#include "job/option_table.hpp"

namespace spt::job {

namespace {

const char* kind_name(OptionKind k) {
    switch (k) {
        case OptionKind::Flag: return "flag";
        case OptionKind::Integer: return "integer";
        case OptionKind::Number: return "number";
        case OptionKind::Choice: return "choice";
        case OptionKind::Text: return "text";
        case OptionKind::Path: return "path";
        case OptionKind::List: return "list";
    }
    return "text";
}

const char* scope_name(OptionScope s) {
    switch (s) {
        case OptionScope::Painting: return "painting";
        case OptionScope::Shot: return "shot";
        case OptionScope::Run: return "run";
        case OptionScope::Planning: return "planning";
    }
    return "painting";
}

}  // namespace

std::string options_json() {
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const OptionRow& r : option_rows()) {
        nlohmann::ordered_json o;
        o["name"] = r.name;
        o["kind"] = kind_name(r.kind);
        if (!r.metavar.empty()) o["metavar"] = r.metavar;
        if (!r.def.empty()) o["default"] = r.def;
        if (r.kind == OptionKind::Integer) { o["min"] = long(r.lo); o["max"] = long(r.hi); }
        if (r.kind == OptionKind::Number) { o["min"] = r.lo; o["max"] = r.hi; }
        if (!r.unit.empty()) o["unit"] = r.unit;
        if (!r.choices.empty()) o["choices"] = r.choices;
        o["help"] = r.help;
        nlohmann::ordered_json styles = nlohmann::ordered_json::array();
        for (Style s : {Style::Painterly, Style::Cartoon})
            if (r.styles & style_bit(s)) styles.push_back(style_name(s));
        o["styles"] = styles;
        o["scope"] = scope_name(r.scope);
        nlohmann::ordered_json commands = nlohmann::ordered_json::array();
        if (r.commands & kForPaint) commands.push_back("paint");
        if (r.commands & kForPlan) commands.push_back("plan");
        o["commands"] = commands;
        if (!r.group.empty()) o["group"] = r.group;
        o["addon"] = r.addon;
        rows.push_back(std::move(o));
    }
    nlohmann::ordered_json doc;
    doc["format"] = "spt-paint-options";
    doc["version"] = 1;
    doc["options"] = std::move(rows);
    return doc.dump(1) + "\n";
}

}  // namespace spt::job
