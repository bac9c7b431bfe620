// Shared command-line parser (see args.hpp).
#include "cli/args.hpp"

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace spt::cli {

Args::Args(std::string command, std::string summary, std::string usage)
    : command_(std::move(command)), summary_(std::move(summary)), usage_(std::move(usage)) {
    flag("help", "show this help and exit", 'h');
}

Args& Args::flag(const std::string& name, const std::string& help, char short_name) {
    opts_.push_back({name, "", help, "", short_name, Kind::Flag});
    return *this;
}

Args& Args::option(const std::string& name, const std::string& metavar, const std::string& help,
                   char short_name, const std::string& def) {
    opts_.push_back({name, metavar, help, def, short_name, Kind::Option});
    return *this;
}

Args& Args::multi(const std::string& name, const std::string& metavar, const std::string& help,
                  char short_name) {
    opts_.push_back({name, metavar, help, "", short_name, Kind::Multi});
    return *this;
}

Args& Args::positional(const std::string& name, const std::string& help, bool required,
                       bool variadic) {
    pos_.push_back({name, help, required, variadic});
    return *this;
}

Args& Args::epilog(const std::string& text) {
    epilog_ = text;
    return *this;
}

const Args::Opt* Args::find_long(const std::string& name) const {
    for (const auto& o : opts_)
        if (o.name == name) return &o;
    return nullptr;
}

const Args::Opt* Args::find_short(char c) const {
    for (const auto& o : opts_)
        if (o.short_name == c) return &o;
    return nullptr;
}

int Args::usage_error(const std::string& msg) const {
    std::fprintf(stderr, "spt %s: %s\n(see 'spt %s --help')\n", command_.c_str(), msg.c_str(),
                 command_.c_str());
    return 2;
}

int Args::parse(int argc, char** argv) {
    std::vector<std::string> positionals;
    bool options_done = false;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (options_done || a.size() < 2 || a[0] != '-' ||
            (a.size() > 1 && (std::isdigit(static_cast<unsigned char>(a[1])) || a[1] == '.'))) {
            positionals.push_back(a);  // "-" alone (stdin/stdout) and negative numbers too
            continue;
        }
        if (a == "--") {
            options_done = true;
            continue;
        }
        const Opt* o = nullptr;
        std::optional<std::string> inline_value;
        std::string shown = a;
        if (a[1] == '-') {
            std::string name = a.substr(2);
            if (size_t eq = name.find('='); eq != std::string::npos) {
                inline_value = name.substr(eq + 1);
                name = name.substr(0, eq);
                shown = "--" + name;
            }
            o = find_long(name);
        } else if (a.size() == 2) {
            o = find_short(a[1]);
        } else if (a.size() > 2 && (o = find_short(a[1])) && o->kind != Kind::Flag) {
            inline_value = a.substr(2);  // -oOUT
            shown = a.substr(0, 2);
        } else {
            o = nullptr;
        }
        if (!o) return usage_error("unknown option '" + shown + "'");
        if (o->kind == Kind::Flag) {
            if (inline_value) return usage_error(shown + " takes no value");
            values_[o->name].push_back("1");
        } else {
            std::string v;
            if (inline_value) {
                v = *inline_value;
            } else {
                if (i + 1 >= argc) return usage_error(shown + " needs a value (" + o->metavar + ")");
                v = argv[++i];
            }
            values_[o->name].push_back(v);
        }
    }
    if (has("help")) {
        std::fputs(help_text().c_str(), stdout);
        return 0;
    }
    size_t k = 0;
    for (const auto& p : pos_) {
        if (p.variadic) {
            for (; k < positionals.size(); ++k) pos_values_[p.name].push_back(positionals[k]);
            if (p.required && pos_values_[p.name].empty()) return usage_error("missing " + p.name);
            continue;
        }
        if (k < positionals.size()) {
            pos_values_[p.name].push_back(positionals[k++]);
        } else if (p.required) {
            return usage_error("missing " + p.name);
        }
    }
    if (k < positionals.size()) return usage_error("unexpected argument '" + positionals[k] + "'");
    return -1;
}

bool Args::has(const std::string& name) const {
    auto it = values_.find(name);
    return it != values_.end() && !it->second.empty();
}

std::string Args::get(const std::string& name) const {
    auto it = values_.find(name);
    if (it != values_.end() && !it->second.empty()) return it->second.back();
    const Opt* o = find_long(name);
    return o ? o->def : std::string();
}

std::vector<std::string> Args::all(const std::string& name) const {
    auto it = values_.find(name);
    return it == values_.end() ? std::vector<std::string>{} : it->second;
}

std::string Args::pos(const std::string& name) const {
    auto it = pos_values_.find(name);
    return it == pos_values_.end() || it->second.empty() ? std::string() : it->second.front();
}

std::vector<std::string> Args::pos_all(const std::string& name) const {
    auto it = pos_values_.find(name);
    return it == pos_values_.end() ? std::vector<std::string>{} : it->second;
}

bool Args::get_long(const std::string& name, long& out, long min, long max) const {
    if (!has(name)) return true;
    const std::string v = get(name);
    errno = 0;
    char* end = nullptr;
    const long x = std::strtol(v.c_str(), &end, 10);
    if (v.empty() || *end != '\0' || errno == ERANGE) {
        usage_error("--" + name + ": expected an integer, got '" + v + "'");
        return false;
    }
    if (x < min || x > max) {
        usage_error("--" + name + ": " + v + " is out of range [" + std::to_string(min) + ", " +
                    std::to_string(max) + "]");
        return false;
    }
    out = x;
    return true;
}

bool Args::get_double(const std::string& name, double& out) const {
    if (!has(name)) return true;
    const std::string v = get(name);
    char* end = nullptr;
    const double x = std::strtod(v.c_str(), &end);
    if (v.empty() || *end != '\0' || !std::isfinite(x)) {
        usage_error("--" + name + ": expected a number, got '" + v + "'");
        return false;
    }
    out = x;
    return true;
}

std::string Args::help_text() const {
    std::string h = "spt " + command_ + ": " + summary_ + "\n\nusage: " + usage_ + "\n";
    auto wrap_line = [&](std::string left, const std::string& text) {
        if (left.size() < 26) left.resize(26, ' ');
        else left += "\n" + std::string(26, ' ');
        // Wrap the help text at ~100 columns, continuing under the text column.
        std::string out;
        size_t col = 26;
        size_t p = 0;
        while (p < text.size()) {
            size_t sp = text.find(' ', p);
            if (sp == std::string::npos) sp = text.size();
            std::string word = text.substr(p, sp - p);
            if (col + word.size() > 100 && col > 26) {
                out += "\n" + std::string(26, ' ');
                col = 26;
            }
            out += word;
            col += word.size();
            if (sp < text.size()) {
                out += ' ';
                ++col;
            }
            p = sp + 1;
        }
        h += "  " + left + out + "\n";
    };
    if (!pos_.empty()) {
        h += "\narguments:\n";
        for (const auto& p : pos_)
            wrap_line(p.name + (p.variadic ? "..." : ""), p.help + (p.required ? "" : " (optional)"));
    }
    h += "\noptions:\n";
    for (const auto& o : opts_) {
        std::string left = o.short_name ? std::string("-") + o.short_name + ", " : std::string("    ");
        left += "--" + o.name;
        if (o.kind != Kind::Flag) left += " " + o.metavar;
        std::string text = o.help;
        if (!o.def.empty()) text += " (default: " + o.def + ")";
        if (o.kind == Kind::Multi) text += " (repeatable)";
        wrap_line(left, text);
    }
    if (!epilog_.empty()) h += "\n" + epilog_ + (epilog_.back() == '\n' ? "" : "\n");
    return h;
}

}  // namespace spt::cli
