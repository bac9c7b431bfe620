// The shared command-line layer (see args.hpp) on CLI11.
#include "cli/args.hpp"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <CLI/CLI.hpp>

namespace spt::cli {

namespace {

// spt's help layout: "spt CMD: summary", the hand-written synopsis (it says more than a list of
// option names), the generated argument and option lists (wrapped at 100 columns, the text in
// a column of its own), then the epilog.
class HelpFormatter : public CLI::Formatter {
public:
    HelpFormatter(std::string title, std::string usage) : title_(std::move(title)), usage_(std::move(usage)) {
        column_width(kColumn);
    }
    std::string make_help(const CLI::App* app, std::string, CLI::AppFormatMode) const override {
        std::string out = title_ + "\n\nusage: " + usage_ + "\n";
        out += make_group("arguments", true, app->get_options([](const CLI::Option* o) { return o->get_positional(); }));
        for (const std::string& g : app->get_groups())
            out += make_group(g, false, app->get_options([&](const CLI::Option* o) {
                return o->get_group() == g && o->nonpositional();
            }));
        // The epilog, each line wrapped at kWidth.
        const std::string f = app->get_footer();
        if (!f.empty()) out += "\n";
        for (size_t p = 0; p < f.size();) {
            size_t nl = f.find('\n', p);
            if (nl == std::string::npos) nl = f.size();
            out += wrap(std::string(), f.substr(p, nl - p), 0);
            p = nl + 1;
        }
        return out;
    }
    std::string make_group(std::string group, bool positional, std::vector<const CLI::Option*> opts) const override {
        if (opts.empty()) return {};
        std::string out = "\n" + group + ":\n";
        for (const CLI::Option* o : opts) out += make_option(o, positional);
        return out;
    }
    std::string make_option(const CLI::Option* opt, bool positional) const override {
        std::string left = "  ";
        if (positional) {
            left += opt->get_name() + (opt->get_expected_max() > 1 ? "..." : "");
        } else {
            const auto& s = opt->get_snames();
            left += s.empty() ? "    " : "-" + s.front() + ", ";
            left += "--" + opt->get_lnames().front();
            if (!opt->get_type_name().empty()) left += " " + opt->get_type_name();
        }
        return wrap(left, opt->get_description(), kColumn);
    }

private:
    static constexpr size_t kColumn = 30, kWidth = 100;
    // `left` padded to `column` (or on a line of its own when longer), then `text` wrapped at
    // kWidth, continued under `column`.
    static std::string wrap(std::string left, const std::string& text, size_t column) {
        if (left.size() < column) left.resize(column, ' ');
        else if (!left.empty()) left += "\n" + std::string(column, ' ');
        size_t col = column;
        for (size_t p = 0; p < text.size();) {
            size_t sp = text.find(' ', p);
            if (sp == std::string::npos) sp = text.size();
            const size_t n = sp - p;
            if (col + n > kWidth && col > column) {
                while (!left.empty() && left.back() == ' ') left.pop_back();
                left += "\n" + std::string(column, ' ');
                col = column;
            }
            left.append(text, p, n);
            col += n;
            if (sp < text.size()) { left += ' '; ++col; }
            p = sp + 1;
        }
        return left + "\n";
    }
    std::string title_, usage_;
};

}  // namespace

struct Args::Impl {
    enum class Kind { Flag, Option, Multi };
    struct Opt {
        std::string name;
        Kind kind;
        CLI::Option* cli;
    };
    struct Pos {
        std::string name;
        CLI::Option* cli;
        bool required;
    };
    CLI::App app;
    std::vector<Opt> opts;
    std::vector<Pos> pos;
    std::string group = "options";

    Impl(const std::string& command, const std::string& summary, const std::string& usage)
        : app(summary, "spt " + command) {
        app.formatter(std::make_shared<HelpFormatter>("spt " + command + ": " + summary, usage));
        app.set_help_flag("-h,--help", "show this help and exit")->group("options");
    }

    static std::string names(const std::string& name, char short_name) {
        return (short_name ? std::string("-") + short_name + "," : std::string()) + "--" + name;
    }
};

Args::Args(std::string command, std::string summary, std::string usage)
    : impl_(std::make_unique<Impl>(command, summary, usage)), command_(std::move(command)) {}

Args::~Args() = default;

Args& Args::flag(const std::string& name, const std::string& help, char short_name) {
    CLI::Option* o = impl_->app.add_flag(Impl::names(name, short_name), help);
    o->group(impl_->group)->disable_flag_override();
    impl_->opts.push_back({name, Impl::Kind::Flag, o});
    return *this;
}

Args& Args::option(const std::string& name, const std::string& metavar, const std::string& help,
                   char short_name, const std::string& def) {
    CLI::Option* o = impl_->app.add_option(Impl::names(name, short_name));
    o->description(def.empty() ? help : help + " (default: " + def + ")");
    o->type_name(metavar)->multi_option_policy(CLI::MultiOptionPolicy::TakeLast)->group(impl_->group);
    impl_->opts.push_back({name, Impl::Kind::Option, o});
    if (!def.empty()) defaults_[name] = def;
    return *this;
}

Args& Args::multi(const std::string& name, const std::string& metavar, const std::string& help,
                  char short_name) {
    CLI::Option* o = impl_->app.add_option(Impl::names(name, short_name));
    o->description(help + " (repeatable)");
    o->type_name(metavar)->expected(1)->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)->group(impl_->group);
    impl_->opts.push_back({name, Impl::Kind::Multi, o});
    return *this;
}

Args& Args::positional(const std::string& name, const std::string& help, bool required,
                       bool variadic) {
    CLI::Option* o = impl_->app.add_option(name);
    o->description(required ? help : help + " (optional)");
    o->type_name("");
    if (variadic)
        o->expected(required ? 1 : 0, CLI::detail::expected_max_vector_size)
            ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
            ->allow_extra_args();
    // Required here, not in CLI11: CLI11 reports a missing argument before an unknown option,
    // and `spt paint --bogus` should name --bogus.
    impl_->pos.push_back({name, o, required});
    return *this;
}

Args& Args::group(const std::string& title) {
    impl_->group = title;
    return *this;
}

Args& Args::epilog(const std::string& text) {
    impl_->app.footer(text);
    return *this;
}

int Args::usage_error(const std::string& msg) const {
    std::fprintf(stderr, "spt %s: %s\n(see 'spt %s --help')\n", command_.c_str(), msg.c_str(),
                 command_.c_str());
    return 2;
}

int Args::parse(int argc, char** argv) {
    try {
        impl_->app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
        std::fputs(help_text().c_str(), stdout);
        return 0;
    } catch (const CLI::ParseError& e) {
        return usage_error(e.what());
    }
    for (const auto& o : impl_->opts) {
        if (o.kind == Impl::Kind::Flag) {
            for (size_t i = 0; i < o.cli->count(); ++i) values_[o.name].push_back("1");
        } else if (!o.cli->results().empty()) {
            values_[o.name] = o.cli->results();
        }
    }
    for (const auto& p : impl_->pos) {
        if (p.required && p.cli->results().empty()) return usage_error(p.name + " is required");
        if (!p.cli->results().empty()) pos_values_[p.name] = p.cli->results();
    }
    return -1;
}

bool Args::has(const std::string& name) const {
    auto it = values_.find(name);
    return it != values_.end() && !it->second.empty();
}

std::string Args::get(const std::string& name) const {
    auto it = values_.find(name);
    if (it != values_.end() && !it->second.empty()) return it->second.back();
    auto d = defaults_.find(name);
    return d == defaults_.end() ? std::string() : d->second;
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

bool Args::get_progress(io::ProgressMode& out) const {
    if (io::parse_progress_mode(get("progress"), out)) return true;
    usage_error("--progress: expected auto, plain, json or none");
    return false;
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

std::string Args::help_text() const { return impl_->app.help(); }

}  // namespace spt::cli
