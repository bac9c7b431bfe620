// A clean stop on SIGINT or SIGTERM for the sequence painters: the first signal asks them to
// stop after the frame they are painting and finish a valid file of the frames done (exit 3,
// kExitInterrupted); a second one ends the process the default way (the output is then an
// unnamed file that vanishes with it, never anything under its final name:
// spt/atomic_file.hpp).
#pragma once

namespace spt::video {

class StopSignals {
public:
    // Installs the handlers for the guard's lifetime (and clears an earlier request); with
    // `install` false it only reads the request flag.
    explicit StopSignals(bool install);
    ~StopSignals();
    StopSignals(const StopSignals&) = delete;
    StopSignals& operator=(const StopSignals&) = delete;
    // True once a signal asked for a stop.
    static bool requested();

private:
    bool installed_;
    void (*old_int_)(int) = nullptr;
    void (*old_term_)(int) = nullptr;
};

}  // namespace spt::video
