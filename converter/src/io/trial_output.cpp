#include "io/trial_output.hpp"

#include <cstdio>

namespace spt::io {

Result<TrialOutput> TrialOutput::create(const std::string& output) {
    auto f = AtomicFile::create(output);
    if (!f) return f.error();
    TrialOutput t;
    t.file_ = std::move(*f);
    t.output_ = output;
#if defined(__linux__)
    t.path_ = "/proc/self/fd/" + std::to_string(::fileno(t.file_.stream()));
#else
    t.path_ = "/dev/fd/" + std::to_string(::fileno(t.file_.stream()));
#endif
    return t;
}

std::string TrialOutput::explain(std::string message) const {
    const std::string by = output_ + " (a trial of the rate search)";
    for (size_t p = message.find(path_); p != std::string::npos; p = message.find(path_, p + by.size()))
        message.replace(p, path_.size(), by);
    return message;
}

Status TrialOutput::keep() {
    Status s = file_.commit();
    if (!s) return make_error(s.error().code, explain(s.error().message));
    return s;
}

}  // namespace spt::io
