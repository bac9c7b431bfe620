#include "cli/paint_progress.hpp"

#include <algorithm>
#include <cstdio>

#include "spt_json/write.hpp"

namespace spt::cli {

namespace {
double secs(std::chrono::steady_clock::duration d) { return std::chrono::duration<double>(d).count(); }
}

PaintProgress::PaintProgress(io::ProgressMode mode, uint64_t max_strokes, double target_psnr, int sets)
    : mode_(mode), max_strokes_(max_strokes), target_(target_psnr), sets_(sets),
      start_(std::chrono::steady_clock::now()), last_(start_) {
    if (mode_ != io::ProgressMode::Json && mode_ != io::ProgressMode::None)
        bar_ = std::make_unique<io::Progress>(mode_, "paint", target_ > 0 ? target_ : double(max_strokes_));
}

void PaintProgress::json(const char* event, uint64_t strokes, int set, double psnr, int ok, const std::string& detail) {
    const double done = target_ > 0 ? std::min(psnr, target_) : double(strokes);
    const double total = target_ > 0 ? target_ : double(max_strokes_);
    json::Doc j = {{"event", event}, {"task", "paint"}, {"done", json::number(done)}, {"total", json::number(total)},
                   {"strokes", strokes}, {"psnr", json::number(psnr)},
                   {"elapsed", json::number(secs(std::chrono::steady_clock::now() - start_))}};
    if (set >= 0) {
        j["set"] = set;
        j["sets"] = sets_;
    }
    if (ok >= 0) j["ok"] = ok != 0;
    if (!detail.empty()) j["detail"] = detail;
    std::fputs(json::dump(j).c_str(), stdout);
    std::fputc('\n', stdout);
    std::fflush(stdout);
}

void PaintProgress::update(uint64_t strokes, int set, double psnr) {
    if (mode_ == io::ProgressMode::None) return;
    if (mode_ == io::ProgressMode::Json) {
        const auto now = std::chrono::steady_clock::now();
        if (secs(now - last_) < 0.2) return;
        last_ = now;
        json("progress", strokes, set, psnr, -1, {});
        return;
    }
    char detail[96];
    std::snprintf(detail, sizeof detail, "set %d/%d, %llu strokes, %.2f dB", set + 1, sets_,
                  static_cast<unsigned long long>(strokes), psnr);
    bar_->update(target_ > 0 ? std::min(psnr, target_) : double(strokes), detail);
}

void PaintProgress::finish(bool ok, uint64_t strokes, double psnr, const std::string& detail) {
    if (mode_ == io::ProgressMode::None) return;
    if (mode_ == io::ProgressMode::Json) {
        json("end", strokes, -1, psnr, ok ? 1 : 0, detail);
        return;
    }
    bar_->finish(ok, detail);
}

}  // namespace spt::cli
