#include "cartoon/thinning.hpp"

#include <vector>

namespace spt::cartoon {

namespace {

// One sub-iteration: every pixel the rule removes, judged on the image as it was before it
// (the marks are applied after the pass). True when something was removed.
bool thin_pass(cv::Mat& img, int iter, std::vector<cv::Point>& removed) {
    removed.clear();
    for (int i = 1; i < img.rows - 1; ++i) {
        const uint8_t* up = img.ptr<uint8_t>(i - 1);
        const uint8_t* row = img.ptr<uint8_t>(i);
        const uint8_t* down = img.ptr<uint8_t>(i + 1);
        for (int j = 1; j < img.cols - 1; ++j) {
            if (!row[j]) continue;  // only set pixels can go
            // p9 p2 p3
            // p8 p1 p4
            // p7 p6 p5
            const int p2 = up[j], p3 = up[j + 1], p4 = row[j + 1], p5 = down[j + 1];
            const int p6 = down[j], p7 = down[j - 1], p8 = row[j - 1], p9 = up[j - 1];
            const int a = (p2 == 0 && p3 == 1) + (p3 == 0 && p4 == 1) + (p4 == 0 && p5 == 1) + (p5 == 0 && p6 == 1) +
                          (p6 == 0 && p7 == 1) + (p7 == 0 && p8 == 1) + (p8 == 0 && p9 == 1) + (p9 == 0 && p2 == 1);
            const int b = p2 + p3 + p4 + p5 + p6 + p7 + p8 + p9;
            const int m1 = iter == 0 ? p2 * p4 * p6 : p2 * p4 * p8;
            const int m2 = iter == 0 ? p4 * p6 * p8 : p2 * p6 * p8;
            if (a == 1 && b >= 2 && b <= 6 && m1 == 0 && m2 == 0) removed.emplace_back(j, i);
        }
    }
    for (const cv::Point& p : removed) img.at<uint8_t>(p) = 0;
    return !removed.empty();
}

}  // namespace

void thin_zhang_suen(const cv::Mat& mask, cv::Mat& out) {
    CV_Assert(mask.type() == CV_8UC1);
    cv::Mat img(mask.size(), CV_8UC1);
    for (int y = 0; y < mask.rows; ++y) {
        const uint8_t* s = mask.ptr<uint8_t>(y);
        uint8_t* d = img.ptr<uint8_t>(y);
        for (int x = 0; x < mask.cols; ++x) d[x] = s[x] >= 128 ? 1 : 0;
    }
    std::vector<cv::Point> removed;
    for (;;) {
        const bool a = thin_pass(img, 0, removed);
        const bool b = thin_pass(img, 1, removed);
        if (!a && !b) break;
    }
    out = img * 255;
}

}  // namespace spt::cartoon
