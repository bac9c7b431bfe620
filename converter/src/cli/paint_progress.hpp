// Progress of one painting: spt::io::Progress draws the bar and the plain lines; JSON mode
// writes its own objects because they carry the painter's figures as fields
// ({"event":"progress","done":..,"total":..,"strokes":..,"psnr":..,"set":..}) for the add-on.
#pragma once

#include <chrono>
#include <memory>
#include <string>

#include "io/progress.hpp"

namespace spt::cli {

class PaintProgress {
public:
    // With a PSNR target the work is measured in dB towards it, otherwise in strokes.
    PaintProgress(io::ProgressMode mode, uint64_t max_strokes, double target_psnr, int sets);
    void update(uint64_t strokes, int set, double psnr);
    void finish(bool ok, uint64_t strokes, double psnr, const std::string& detail);

private:
    void json(const char* event, uint64_t strokes, int set, double psnr, int ok, const std::string& detail);
    io::ProgressMode mode_;
    uint64_t max_strokes_;
    double target_;
    int sets_;
    std::unique_ptr<io::Progress> bar_;
    std::chrono::steady_clock::time_point start_, last_;
};

}  // namespace spt::cli
