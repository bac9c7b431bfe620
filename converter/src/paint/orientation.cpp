// Multiscale edge detection and orientation fields (paper section 2.2: "from a pixel location we
// search for the nearest edge, calculate its gradient, and let the stroke take this orientation").
#include "paint/orientation.hpp"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

namespace spt::paint {

namespace {

cv::Mat luminance(const ImageView& img) {
    cv::Mat rgb(int(img.height), int(img.width), CV_8UC3, const_cast<uint8_t*>(img.rgb));
    cv::Mat gray;
    cv::cvtColor(rgb, gray, cv::COLOR_RGB2GRAY);
    cv::Mat f;
    gray.convertTo(f, CV_32F);
    return f;
}

struct ScaleLevel {
    double sigma = 1;
    cv::Mat gx, gy, mag;  // mag: gamma-normalised gradient magnitude
    cv::Mat edge;         // CV_8U, 255 on non-maximum-suppressed edge points
};

// Lindeberg's gamma-normalised first derivatives: d_xi = t^(gamma/2) d_x with t = sigma^2. For
// edges gamma = 1/2, so a step edge's normalised strength falls slowly across scales while
// texture (noise) falls fast: what persists over scales is a real edge.
constexpr double kGamma = 0.5;
// Minimum normalised gradient (8-bit grey levels per pixel, sigma^gamma scaled) of an edge.
constexpr float kEdgeThreshold = 3.0f;

ScaleLevel make_level(const cv::Mat& gray, double sigma) {
    ScaleLevel s;
    s.sigma = sigma;
    cv::Mat L;
    cv::GaussianBlur(gray, L, cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
    cv::Sobel(L, s.gx, CV_32F, 1, 0, 3, 1.0 / 8.0, 0, cv::BORDER_REPLICATE);
    cv::Sobel(L, s.gy, CV_32F, 0, 1, 3, 1.0 / 8.0, 0, cv::BORDER_REPLICATE);
    cv::magnitude(s.gx, s.gy, s.mag);
    s.mag *= std::pow(sigma, kGamma);

    // Non-maximum suppression along the gradient (the edge condition L_vv = 0, L_vvv < 0 on the
    // pixel grid): a pixel is an edge point if its magnitude is a maximum across the edge.
    const int w = gray.cols, h = gray.rows;
    s.edge = cv::Mat::zeros(h, w, CV_8U);
    for (int y = 1; y + 1 < h; ++y) {
        const float* m0 = s.mag.ptr<float>(y - 1);
        const float* m1 = s.mag.ptr<float>(y);
        const float* m2 = s.mag.ptr<float>(y + 1);
        const float* gxr = s.gx.ptr<float>(y);
        const float* gyr = s.gy.ptr<float>(y);
        uint8_t* e = s.edge.ptr<uint8_t>(y);
        for (int x = 1; x + 1 < w; ++x) {
            const float m = m1[x];
            if (m < kEdgeThreshold) continue;
            const float ax = std::fabs(gxr[x]), ay = std::fabs(gyr[x]);
            float a, b;
            if (ay <= 0.4142f * ax) {          // gradient ~ horizontal: compare left/right
                a = m1[x - 1]; b = m1[x + 1];
            } else if (ax <= 0.4142f * ay) {   // ~ vertical: up/down
                a = m0[x]; b = m2[x];
            } else if ((gxr[x] > 0) == (gyr[x] > 0)) {  // ~ 45 degrees (y down)
                a = m0[x - 1]; b = m2[x + 1];
            } else {
                a = m0[x + 1]; b = m2[x - 1];
            }
            if (m >= a && m > b) e[x] = 255;
        }
    }
    return s;
}

}  // namespace

EdgeMap multiscale_edges(const ImageView& img) {
    EdgeMap out;
    out.width = img.width;
    out.height = img.height;
    const size_t n = size_t(img.width) * img.height;
    out.edge.assign(n, 0);
    out.grad_angle.assign(n, 0.f);
    if (n == 0) return out;

    const cv::Mat gray = luminance(img);
    // Scales sigma = 1, 2, 4 (and 8 on large images): one octave apart, as scale-space edge
    // tracking needs, and no coarser than the image can hold.
    std::vector<ScaleLevel> levels;
    const double max_sigma = std::max(1.0, std::min(img.width, img.height) / 32.0);
    for (double s = 1; s <= std::min(8.0, max_sigma) || levels.empty(); s *= 2)
        levels.push_back(make_level(gray, s));

    // Persistence: an edge point of the finest scale is kept when the edge is still there at the
    // coarser scales (within a neighbourhood of the coarser scale's sigma, since edges drift as
    // they blur). This keeps the main contours and drops texture, as the paper's figure 5 shows.
    const int w = int(img.width), h = int(img.height);
    cv::Mat support = cv::Mat::zeros(h, w, CV_8U);
    for (size_t k = 1; k < levels.size(); ++k) {
        const int r = int(std::lround(levels[k].sigma));
        cv::Mat dil;
        cv::dilate(levels[k].edge, dil,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(2 * r + 1, 2 * r + 1)));
        support += dil / 255;
    }
    const int need = std::min<int>(2, int(levels.size()) - 1);
    for (int y = 0; y < h; ++y) {
        const uint8_t* e0 = levels[0].edge.ptr<uint8_t>(y);
        const uint8_t* sp = support.ptr<uint8_t>(y);
        for (int x = 0; x < w; ++x) {
            const size_t i = size_t(y) * w + x;
            // Scale selection: the direction comes from the scale where the normalised
            // gradient peaks (Lindeberg's selected scale), the most reliable one for this edge.
            size_t best = 0;
            float bm = -1;
            for (size_t k = 0; k < levels.size(); ++k) {
                const float m = levels[k].mag.at<float>(y, x);
                if (m > bm) { bm = m; best = k; }
            }
            out.grad_angle[i] = std::atan2(levels[best].gy.at<float>(y, x), levels[best].gx.at<float>(y, x));
            if (e0[x] && sp[x] >= need) out.edge[i] = 255;
        }
    }
    return out;
}

uint8_t nearest_orientation(const std::vector<Orientation>& table, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    uint8_t best = 0;
    double bd = -1;
    for (size_t k = 0; k < table.size(); ++k) {
        // Strokes are symmetric under a half turn: compare undirected axes.
        const double d = std::fabs(c * table[k].cos_q14 + s * table[k].sin_q14);
        if (d > bd) { bd = d; best = uint8_t(k); }
    }
    return best;
}

namespace {

// Orientation indices for a quantised angle grid, so that the per-pixel loop does no trig.
struct AngleQuantiser {
    static constexpr int kBins = 720;
    std::vector<uint8_t> lut;
    explicit AngleQuantiser(const std::vector<Orientation>& table) : lut(kBins) {
        for (int i = 0; i < kBins; ++i) lut[i] = nearest_orientation(table, (i + 0.5) * M_PI / kBins);
    }
    // theta: direction of the stroke axis, any range.
    uint8_t operator()(double theta) const {
        double t = std::fmod(theta, M_PI);
        if (t < 0) t += M_PI;
        int i = int(t * kBins / M_PI);
        return lut[std::clamp(i, 0, kBins - 1)];
    }
};

std::vector<uint8_t> gradient_field(const ImageView& img, const AngleQuantiser& q) {
    const cv::Mat gray = luminance(img);
    cv::Mat gx, gy;
    cv::Sobel(gray, gx, CV_32F, 1, 0, 3, 1.0 / 8.0, 0, cv::BORDER_REPLICATE);
    cv::Sobel(gray, gy, CV_32F, 0, 1, 3, 1.0 / 8.0, 0, cv::BORDER_REPLICATE);
    // Structure tensor smoothed over a few pixels: the dominant local gradient direction, stable
    // where a single-pixel gradient is noise.
    cv::Mat jxx = gx.mul(gx), jyy = gy.mul(gy), jxy = gx.mul(gy);
    const double rho = 3.0;
    cv::GaussianBlur(jxx, jxx, cv::Size(0, 0), rho, rho, cv::BORDER_REPLICATE);
    cv::GaussianBlur(jyy, jyy, cv::Size(0, 0), rho, rho, cv::BORDER_REPLICATE);
    cv::GaussianBlur(jxy, jxy, cv::Size(0, 0), rho, rho, cv::BORDER_REPLICATE);
    std::vector<uint8_t> out(size_t(img.width) * img.height);
    for (int y = 0; y < gray.rows; ++y)
        for (int x = 0; x < gray.cols; ++x) {
            const double a = jxx.at<float>(y, x), b = jyy.at<float>(y, x), c = jxy.at<float>(y, x);
            const double grad = 0.5 * std::atan2(2 * c, a - b);
            out[size_t(y) * img.width + x] = q(grad + M_PI / 2);
        }
    return out;
}

}  // namespace

std::vector<uint8_t> orientation_field(const ImageView& img, const std::vector<Orientation>& table,
                                       OrientMode mode) {
    if (mode == OrientMode::Random || table.empty() || img.width == 0 || img.height == 0) return {};
    const AngleQuantiser q(table);
    if (mode == OrientMode::Gradient) return gradient_field(img, q);

    const EdgeMap em = multiscale_edges(img);
    const int w = int(img.width), h = int(img.height);
    cv::Mat src(h, w, CV_8U);
    bool any = false;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const bool e = em.edge[size_t(y) * w + x] != 0;
            src.at<uint8_t>(y, x) = e ? 0 : 255;
            any |= e;
        }
    if (!any) return gradient_field(img, q);  // a flat or blurred image: no edge to follow

    // distanceTransform with DIST_LABEL_PIXEL gives each zero (edge) pixel its own label and
    // every other pixel the label of its nearest edge pixel.
    cv::Mat dist, labels;
    cv::distanceTransform(src, dist, labels, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
    std::vector<uint8_t> label_orient;
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            if (src.at<uint8_t>(y, x) != 0) continue;
            const int lab = labels.at<int>(y, x);
            if (lab < 0) continue;
            if (size_t(lab) >= label_orient.size()) label_orient.resize(size_t(lab) + 1, 0);
            label_orient[lab] = q(em.grad_angle[size_t(y) * w + x] + M_PI / 2);
        }
    std::vector<uint8_t> out(size_t(w) * h);
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x) {
            const int lab = labels.at<int>(y, x);
            out[size_t(y) * w + x] = (lab >= 0 && size_t(lab) < label_orient.size()) ? label_orient[lab] : 0;
        }
    return out;
}

}  // namespace spt::paint
