// Progress reporting: terminal bar, plain lines, JSON lines (see progress.hpp).
#include "io/progress.hpp"

#include <unistd.h>

#include <algorithm>
#include <cmath>

#include "spt_json/write.hpp"

namespace spt::io {

namespace {

using Clock = std::chrono::steady_clock;

double seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// "1:02:03", "2:03" or "7s".
std::string clock_text(double s) {
    if (!std::isfinite(s) || s < 0) return "?";
    long t = long(s + 0.5);
    char b[32];
    if (t >= 3600)
        std::snprintf(b, sizeof b, "%ld:%02ld:%02ld", t / 3600, t / 60 % 60, t % 60);
    else if (t >= 60)
        std::snprintf(b, sizeof b, "%ld:%02ld", t / 60, t % 60);
    else
        std::snprintf(b, sizeof b, "%lds", t);
    return b;
}

std::string units(double v) {
    char b[32];
    if (v == std::floor(v) && std::fabs(v) < 1e15)
        std::snprintf(b, sizeof b, "%.0f", v);
    else
        std::snprintf(b, sizeof b, "%.1f", v);
    return b;
}

}  // namespace

bool parse_progress_mode(const std::string& s, ProgressMode& out) {
    if (s == "auto") out = ProgressMode::Auto;
    else if (s == "plain") out = ProgressMode::Plain;
    else if (s == "json") out = ProgressMode::Json;
    else if (s == "none") out = ProgressMode::None;
    else return false;
    return true;
}

Progress::Progress(ProgressMode mode, std::string task, double total)
    : mode_(mode), task_(std::move(task)), total_(total) {
    if (mode_ == ProgressMode::Auto) mode_ = isatty(STDERR_FILENO) ? ProgressMode::Auto : ProgressMode::None;
    start_ = last_emit_ = Clock::now();
    if (mode_ == ProgressMode::Json) emit_json("start", 0, {}, -1);
    else if (mode_ == ProgressMode::Plain) {
        std::fprintf(stderr, "%s: started%s\n", task_.c_str(),
                     total_ > 0 ? (" (" + units(total_) + " to do)").c_str() : "");
        std::fflush(stderr);
    }
}

Progress::~Progress() {
    if (!finished_) finish(false);
}

void Progress::set_total(double total) { total_ = total; }

void Progress::update(double done, const std::string& detail) {
    last_done_ = done;
    emit(done, detail, false);
}

void Progress::emit_json(const char* event, double done, const std::string& detail, int ok) {
    const double el = seconds(Clock::now() - start_);
    const double rate = el > 0 ? done / el : 0;
    json::Doc j = {{"event", event}, {"task", task_}, {"done", json::number(done)}};
    j["total"] = total_ > 0 ? json::number(total_) : nullptr;
    j["percent"] = total_ > 0 ? json::number(std::min(100.0, 100.0 * done / total_)) : nullptr;
    j["elapsed"] = json::number(el);
    j["eta"] = total_ > 0 && rate > 0 ? json::number(std::max(0.0, (total_ - done) / rate)) : nullptr;
    j["fps"] = json::number(rate);
    j["detail"] = detail;
    if (ok >= 0) j["ok"] = ok != 0;
    std::fputs(json::dump(j).c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);  // the Blender add-on reads a pipe line by line
}

void Progress::emit(double done, const std::string& detail, bool force) {
    if (mode_ == ProgressMode::None) return;
    const auto now = Clock::now();
    const double since = seconds(now - last_emit_);
    const double min_gap = mode_ == ProgressMode::Plain ? 1.0 : mode_ == ProgressMode::Json ? 0.2 : 0.1;
    if (!force && since < min_gap) return;
    last_emit_ = now;
    if (mode_ == ProgressMode::Json) {
        emit_json("progress", done, detail, -1);
        return;
    }
    const double el = seconds(now - start_);
    const double rate = el > 0 ? done / el : 0;
    const double frac = total_ > 0 ? std::clamp(done / total_, 0.0, 1.0) : 0;
    const std::string eta = (total_ > 0 && rate > 0) ? clock_text((total_ - done) / rate) : "?";
    char rate_text[32];
    std::snprintf(rate_text, sizeof rate_text, "%.2f/s", rate);
    std::string count = units(done);
    if (total_ > 0) count += '/' + units(total_);
    if (mode_ == ProgressMode::Plain) {
        std::fprintf(stderr, "%s: %5.1f%% %s, %s, %s left%s%s\n", task_.c_str(), 100 * frac,
                     count.c_str(), rate_text, eta.c_str(), detail.empty() ? "" : ", ",
                     detail.c_str());
    } else {  // terminal bar, redrawn in place
        constexpr int kWidth = 28;
        const int fill = int(frac * kWidth + 0.5);
        std::string bar(size_t(fill), '#');
        bar.append(size_t(kWidth - fill), '.');
        std::string line = task_ + " [" + bar + "] ";
        char pct[16];
        std::snprintf(pct, sizeof pct, "%5.1f%% ", 100 * frac);
        line += pct;
        line += count;
        line += ' ';
        line += rate_text;
        line += ' ';
        line += eta;
        line += " left";
        if (!detail.empty()) line += " " + detail;
        if (line.size() > 110) line.resize(110);
        std::fprintf(stderr, "\r%s\x1b[K", line.c_str());
        bar_drawn_ = true;
    }
    std::fflush(stderr);
}

void Progress::finish(bool ok, const std::string& detail) {
    if (finished_) return;
    finished_ = true;
    if (mode_ == ProgressMode::None) return;
    if (ok && total_ > 0) last_done_ = std::max(last_done_, total_);
    if (mode_ == ProgressMode::Json) {
        emit_json("end", last_done_, detail, ok ? 1 : 0);
        return;
    }
    const double el = seconds(Clock::now() - start_);
    if (mode_ == ProgressMode::Auto) {
        emit(last_done_, detail, true);
        if (bar_drawn_) std::fputc('\n', stderr);
    }
    std::fprintf(stderr, "%s: %s in %s%s%s\n", task_.c_str(), ok ? "done" : "stopped",
                 clock_text(el).c_str(), detail.empty() ? "" : ", ", detail.c_str());
    std::fflush(stderr);
}

}  // namespace spt::io
