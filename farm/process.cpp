#include "farm/process.hpp"

#include <fcntl.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>

extern char** environ;

namespace spt::farm {

namespace {

// The last non-empty line of a file (its last 4 KiB are enough for one line of a client's
// message; a runaway stderr is not read whole).
std::string last_line(const std::string& path) {
    std::ifstream f(path, std::ios::binary | std::ios::ate);
    if (!f) return {};
    const std::streamoff size = f.tellg();
    const std::streamoff from = size > 4096 ? size - 4096 : 0;
    f.seekg(from);
    std::string e(size_t(size - from), '\0');
    f.read(e.data(), std::streamsize(e.size()));
    e.resize(size_t(f.gcount()));
    while (!e.empty() && (e.back() == '\n' || e.back() == ' ' || e.back() == '\r')) e.pop_back();
    const size_t nl = e.rfind('\n');
    return nl == std::string::npos ? e : e.substr(nl + 1);
}

// Closes a file descriptor once, on every path out.
struct Fd {
    int fd = -1;
    ~Fd() { reset(); }
    void reset() {
        if (fd >= 0) ::close(fd);
        fd = -1;
    }
};

}  // namespace

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

std::string stderr_file_for(const std::string& state_dir, const std::string& command) {
    const size_t slash = command.rfind('/');
    return state_dir + "/logs/" + (slash == std::string::npos ? command : command.substr(slash + 1)) + ".stderr";
}

Result<std::string> run_capture(const std::vector<std::string>& argv, const std::string& stderr_file) {
    if (argv.empty() || argv[0].empty()) return make_error(Code::InvalidArgument, "no command to run");
    const std::string& name = argv[0];
    Fd err, out_r, out_w;
    err.fd = ::open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (err.fd < 0)
        return make_error(Code::IoError, stderr_file + ": cannot write the stderr of " + name + ": " + std::strerror(errno));
    int p[2];
    if (::pipe2(p, O_CLOEXEC) != 0) return make_error(Code::IoError, "cannot run " + name + ": pipe: " + std::strerror(errno));
    out_r.fd = p[0];
    out_w.fd = p[1];

    posix_spawn_file_actions_t fa;
    posix_spawn_file_actions_init(&fa);
    posix_spawn_file_actions_addopen(&fa, 0, "/dev/null", O_RDONLY, 0);
    // dup2 clears close-on-exec on the copies; the originals close at exec.
    posix_spawn_file_actions_adddup2(&fa, out_w.fd, 1);
    posix_spawn_file_actions_adddup2(&fa, err.fd, 2);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    pid_t pid = 0;
    const int rc = posix_spawnp(&pid, name.c_str(), &fa, nullptr, args.data(), environ);
    posix_spawn_file_actions_destroy(&fa);
    out_w.reset();
    err.reset();
    if (rc != 0) return make_error(Code::IoError, "cannot run " + name + ": " + std::strerror(rc));

    std::string out;
    char buf[4096];
    for (;;) {
        const ssize_t n = ::read(out_r.fd, buf, sizeof buf);
        if (n > 0) out.append(buf, size_t(n));
        else if (n == 0 || errno != EINTR) break;
    }
    out_r.reset();
    int st = 0;
    while (::waitpid(pid, &st, 0) < 0) {
        if (errno != EINTR) return make_error(Code::IoError, "cannot wait for " + name + ": " + std::strerror(errno));
    }
    if (WIFEXITED(st) && WEXITSTATUS(st) == 0) return out;
    const std::string how = WIFEXITED(st) ? "exit " + std::to_string(WEXITSTATUS(st))
                                          : "killed by signal " + std::to_string(WTERMSIG(st));
    const std::string e = last_line(stderr_file);
    return make_error(Code::IoError, name + " failed (" + how + ")" + (e.empty() ? std::string() : ": " + e) +
                                         " (its stderr: " + stderr_file + ")");
}

}  // namespace spt::farm
