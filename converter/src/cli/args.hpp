// A small command-line parser shared by the spt sub-commands, so every command accepts the
// same forms and prints the same kind of help and errors:
//   --name value, --name=value, -n value (short alias), flags (--name), repeatable options,
//   positional arguments, "--" ends the options. Unknown options are errors (exit code 2).
//
//   Args a("render", "render a .spt file to images", "spt render FILE.spt -o OUT [options]");
//   a.positional("FILE.spt", "the file to render");
//   a.option("output", "OUT", "output image, sequence pattern or video", 'o');
//   a.flag("json", "print JSON");
//   if (int rc = a.parse(argc, argv); rc >= 0) return rc;   // --help (0) or bad usage (2)
//   std::string out = a.get("output");
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace spt::cli {

class Args {
public:
    // `command` is the sub-command name ("render"); `usage` the synopsis line.
    Args(std::string command, std::string summary, std::string usage);

    // Declarations. `metavar` names the value in help ("N", "FILE"). `def` is shown in help
    // and returned by get() when the option is absent.
    Args& flag(const std::string& name, const std::string& help, char short_name = 0);
    Args& option(const std::string& name, const std::string& metavar, const std::string& help,
                 char short_name = 0, const std::string& def = {});
    Args& multi(const std::string& name, const std::string& metavar, const std::string& help,
                char short_name = 0);
    // Positionals are taken in order; a `variadic` last one takes the rest. Optional ones
    // must come after the required ones.
    Args& positional(const std::string& name, const std::string& help, bool required = true,
                     bool variadic = false);
    // Free text printed after the options in --help (key lists, examples).
    Args& epilog(const std::string& text);

    // Returns -1 when the command should run; otherwise the exit code to return at once:
    // 0 after printing --help to stdout, 2 after printing a usage error to stderr.
    int parse(int argc, char** argv);

    bool has(const std::string& name) const;  // given on the command line (flag or option)
    std::string get(const std::string& name) const;  // last value, or the default
    std::vector<std::string> all(const std::string& name) const;  // every value of a multi
    // Positional values by declared name (variadic: all of them).
    std::string pos(const std::string& name) const;
    std::vector<std::string> pos_all(const std::string& name) const;

    // Typed getters: on a malformed value they print a usage error and return false (the
    // caller then returns 2). Absent options leave `out` unchanged and return true.
    bool get_long(const std::string& name, long& out, long min = -2147483647L,
                  long max = 2147483647L) const;
    bool get_double(const std::string& name, double& out) const;

    // Prints "spt <command>: <msg>" and the --help hint to stderr; returns 2.
    int usage_error(const std::string& msg) const;
    std::string help_text() const;
    const std::string& command() const { return command_; }

private:
    enum class Kind { Flag, Option, Multi };
    struct Opt {
        std::string name, metavar, help, def;
        char short_name = 0;
        Kind kind = Kind::Flag;
    };
    struct Pos {
        std::string name, help;
        bool required = true, variadic = false;
    };
    const Opt* find_long(const std::string& name) const;
    const Opt* find_short(char c) const;

    std::string command_, summary_, usage_, epilog_;
    std::vector<Opt> opts_;
    std::vector<Pos> pos_;
    std::map<std::string, std::vector<std::string>> values_;
    std::map<std::string, std::vector<std::string>> pos_values_;
};

}  // namespace spt::cli
