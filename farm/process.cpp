#include "farm/process.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>

namespace spt::farm {

std::string shell_quote(const std::string& s) {
    std::string q = "'";
    for (char c : s) q += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return q + "'";
}

std::string shell_line(const std::vector<std::string>& argv) {
    std::string line;
    for (const auto& a : argv) line += (line.empty() ? "" : " ") + shell_quote(a);
    return line;
}

Result<std::string> run_capture(const std::vector<std::string>& argv) {
    char err_name[] = "/tmp/spt_farm_stderr_XXXXXX";
    const int fd = mkstemp(err_name);
    if (fd < 0) return make_error(Code::IoError, "cannot create a temporary file for " + argv.at(0));
    close(fd);
    const std::string line = shell_line(argv) + " 2>" + shell_quote(err_name) + " </dev/null";
    std::FILE* p = popen(line.c_str(), "r");
    if (!p) {
        std::remove(err_name);
        return make_error(Code::IoError, "cannot run " + argv.at(0));
    }
    std::string out;
    char buf[4096];
    for (size_t n; (n = std::fread(buf, 1, sizeof buf, p)) > 0;) out.append(buf, n);
    const int st = pclose(p);
    std::ifstream ef(err_name);
    std::stringstream es;
    es << ef.rdbuf();
    std::remove(err_name);
    if (st == -1 || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
        std::string e = es.str();
        while (!e.empty() && (e.back() == '\n' || e.back() == ' ')) e.pop_back();
        const size_t nl = e.rfind('\n');
        if (nl != std::string::npos) e = e.substr(nl + 1);
        const int code = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
        return make_error(Code::IoError, argv.at(0) + " failed (exit " + std::to_string(code) + ")" +
                                             (e.empty() ? std::string() : ": " + e));
    }
    return out;
}

}  // namespace spt::farm
