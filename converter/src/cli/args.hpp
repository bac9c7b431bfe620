// The command-line layer every spt sub-command shares, on CLI11: the same forms everywhere
// (--name value, --name=value, -n value, -nVALUE, flags, repeatable options, positionals, "--"
// ends the options), help generated from the declarations, unknown options and malformed
// values exit 2. This class only keeps spt's conventions (messages, exit codes, typed getters).
//
//   Args a("render", "render a .spt file to images", "spt render FILE.spt -o OUT [options]");
//   a.positional("FILE.spt", "the file to render");
//   a.option("output", "OUT", "output image, sequence pattern or video", 'o');
//   a.flag("json", "print JSON");
//   if (int rc = a.parse(argc, argv); rc >= 0) return rc;   // --help (0) or bad usage (2)
//   std::string out = a.get("output");
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "io/progress.hpp"

namespace spt::cli {

class Args {
public:
    // `command` is the sub-command name ("render"); `usage` the synopsis line.
    Args(std::string command, std::string summary, std::string usage);
    ~Args();
    Args(const Args&) = delete;
    Args& operator=(const Args&) = delete;

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
    // Options declared after this call are listed under `title` in --help.
    Args& group(const std::string& title);
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
    // --progress MODE (io::kProgressHelp): auto, plain, json or none.
    bool get_progress(io::ProgressMode& out) const;

    // Prints "spt <command>: <msg>" and the --help hint to stderr; returns 2.
    int usage_error(const std::string& msg) const;
    std::string help_text() const;
    const std::string& command() const { return command_; }

private:
    struct Impl;  // the CLI11 app (kept out of this header: CLI11 is a heavy include)
    std::unique_ptr<Impl> impl_;
    std::string command_;
    std::map<std::string, std::vector<std::string>> values_;
    std::map<std::string, std::vector<std::string>> pos_values_;
    std::map<std::string, std::string> defaults_;
};

}  // namespace spt::cli
