#include "frames/stop_signal.hpp"

#include <atomic>
#include <csignal>

namespace spt::video {

namespace {

std::atomic<bool> g_signal_stop{false};

extern "C" void on_stop_signal(int sig) {
    if (g_signal_stop.exchange(true)) {
        std::signal(sig, SIG_DFL);
        std::raise(sig);
    }
}

}  // namespace

StopSignals::StopSignals(bool install) : installed_(install) {
    if (!installed_) return;
    g_signal_stop.store(false);
    old_int_ = std::signal(SIGINT, on_stop_signal);
    old_term_ = std::signal(SIGTERM, on_stop_signal);
}

StopSignals::~StopSignals() {
    if (!installed_) return;
    std::signal(SIGINT, old_int_);
    std::signal(SIGTERM, old_term_);
}

bool StopSignals::requested() { return g_signal_stop.load(); }

}  // namespace spt::video
