// Progress reporting for long work: a bar on a terminal, plain lines, or one JSON object per
// line (machine-readable, for the Blender add-on), or nothing.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

namespace spt::io {

enum class ProgressMode { Auto, Plain, Json, None };
bool parse_progress_mode(const std::string& s, ProgressMode& out);

class Progress {
public:
    // Auto: a bar when stderr is a terminal, nothing otherwise.
    Progress(ProgressMode mode, std::string task, double total);
    ~Progress();
    // `done` of `total` units; `detail` is free text ("set 3/6, 1200 strokes").
    void update(double done, const std::string& detail = {});
    void set_total(double total);
    // The final line/object: {"event":"end",...}.
    void finish(bool ok, const std::string& detail = {});
private:
    ProgressMode mode_;
    std::string task_;
    double total_;
    double last_done_ = 0;
    std::chrono::steady_clock::time_point start_, last_emit_;
    bool finished_ = false;
    void emit(double done, const std::string& detail, bool force);
};

}  // namespace spt::io
