// Starts the spt under test as a child process with its output discarded, for the tests that
// must watch the process itself (signals, peak memory) rather than its output.
#pragma once

#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <sys/types.h>
#include <unistd.h>

#include <string>
#include <utility>
#include <vector>

namespace spt_test {

// The child's pid (the caller waits for it); the child exits 127 when spt cannot be started.
inline pid_t spawn_spt_quietly(const std::vector<std::string>& args) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        const int devnull = ::open("/dev/null", O_WRONLY);
        ::dup2(devnull, STDOUT_FILENO);
        ::dup2(devnull, STDERR_FILENO);
        std::vector<char*> argv{const_cast<char*>(SPT_TOOL)};
        for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        ::execv(SPT_TOOL, argv.data());
        ::_exit(127);
    }
    return pid;
}

// Runs spt with `args` (output discarded); its exit code and peak resident size in KiB.
inline std::pair<int, long> run_measured(const std::vector<std::string>& args) {
    const pid_t pid = spawn_spt_quietly(args);
    int st = 0;
    struct rusage ru {};
    ::wait4(pid, &st, 0, &ru);
    return {WIFEXITED(st) ? WEXITSTATUS(st) : -1, ru.ru_maxrss};
}

}  // namespace spt_test
