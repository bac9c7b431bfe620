// Progress reporting for long work: a bar on a terminal, plain lines, or one JSON object per
// line (machine-readable, for the Blender add-on), or nothing.
//
// JSON mode writes to stdout, one object per line, flushed after each line:
//   {"event":"start"|"progress"|"end","task":"paint","done":12,"total":48,"percent":25.0,
//    "elapsed":3.1,"eta":9.3,"fps":3.87,"detail":"..."}
// plus "ok":true|false on the "end" event. "eta" and "percent" are null while the total is
// unknown (total <= 0); "fps" is units done per second (frames for frame tasks).
// Bar and plain modes write to stderr, so stdout stays free for data.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace spt::io {

enum class ProgressMode { Auto, Plain, Json, None };
// Accepts "auto", "plain", "json", "none".
bool parse_progress_mode(const std::string& s, ProgressMode& out);
// The --progress help text shared by commands.
inline constexpr const char* kProgressHelp =
    "auto (a bar when stderr is a terminal, else nothing), plain (a line about every second on "
    "stderr), json (one JSON object per line on stdout), none";

class Progress {
public:
    // Auto: a bar when stderr is a terminal, nothing otherwise. Emits the "start" event.
    Progress(ProgressMode mode, std::string task, double total);
    // Calls finish(false) when finish() was not called (the work was abandoned).
    ~Progress();
    Progress(const Progress&) = delete;
    Progress& operator=(const Progress&) = delete;
    // `done` of `total` units; `detail` is free text ("set 3/6, 1200 strokes").
    void update(double done, const std::string& detail = {});
    void set_total(double total);
    // The final line/object: {"event":"end",...}.
    void finish(bool ok, const std::string& detail = {});
    ProgressMode mode() const { return mode_; }
private:
    ProgressMode mode_;
    std::string task_;
    double total_;
    double last_done_ = 0;
    std::chrono::steady_clock::time_point start_, last_emit_;
    bool finished_ = false;
    bool bar_drawn_ = false;
    void emit(double done, const std::string& detail, bool force);
    void emit_json(const char* event, double done, const std::string& detail, int ok);
};

}  // namespace spt::io
