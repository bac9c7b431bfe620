#include "video/video_scene.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "io/color_config.hpp"
#include "video/ffmpeg_video.hpp"
#include "video/video_reader.hpp"

namespace spt::video {

Result<io::SceneImage> scene_from_frame(const cv::Mat& frame, bool alpha, const io::SceneReadOptions& opts,
                                        const std::string& path) {
    const auto fail = [&](const Error& e) { return make_error(e.code, path + ": " + e.message); };
    auto cs = io::color_config(opts.ocio_config);
    if (!cs) return fail(cs.error());
    auto target = io::linear_rec709_space(*cs);
    if (!target) return fail(target.error());
    auto from = opts.colorspace.empty() ? io::srgb_space(*cs) : io::find_colorspace(*cs, opts.colorspace);
    if (!from) return fail(from.error());
    auto transform = io::color_transform(*cs, *from, *target);
    if (!transform) return fail(transform.error());

    io::SceneImage img;
    if (!cs->warning.empty()) img.warnings.push_back(cs->warning);
    img.width = uint32_t(frame.cols);
    img.height = uint32_t(frame.rows);
    img.has_alpha = alpha;
    img.colorspace = *from;
    img.rgba.resize(size_t(img.width) * img.height * 4);
    const bool deep = frame.depth() == CV_16U;
    for (int y = 0; y < frame.rows; ++y) {
        float* o = img.rgba.data() + size_t(y) * img.width * 4;
        if (deep) {
            const uint16_t* p = frame.ptr<uint16_t>(y);
            for (int x = 0; x < frame.cols; ++x, p += 4, o += 4) {
                for (int k = 0; k < 3; ++k) o[k] = float(p[k]) / 65535.f;
                o[3] = alpha ? float(p[3]) / 65535.f : 1.f;
            }
        } else {
            const uint8_t* p = frame.ptr<uint8_t>(y);
            for (int x = 0; x < frame.cols; ++x, p += 3, o += 4) {
                for (int k = 0; k < 3; ++k) o[k] = float(p[2 - k]) / 255.f;
                o[3] = 1.f;
            }
        }
    }
    // Straight alpha: converted as it is, then premultiplied (scene_image.cpp's PNG path).
    OIIO::ImageSpec bs(int(img.width), int(img.height), 4, OIIO::TypeDesc::FLOAT);
    bs.alpha_channel = 3;
    OIIO::ImageBuf ib(bs, img.rgba.data());
    if (!transform->identity && !OIIO::ImageBufAlgo::colorconvert(ib, ib, transform->processor.get(), false))
        return make_error(Code::Unsupported, path + ": colour conversion from '" + *from + "' failed: " + ib.geterror());
    if (alpha && !OIIO::ImageBufAlgo::premult(ib, ib))
        return make_error(Code::Unsupported, path + ": premultiplying alpha failed: " + ib.geterror());
    size_t negative = 0;
    for (size_t i = 0; i < img.rgba.size(); i += 4)
        for (int k = 0; k < 3; ++k)
            if (!(img.rgba[i + k] >= 0.f)) ++negative, img.rgba[i + k] = 0.f;
    if (negative)
        img.warnings.push_back(path + ": " + std::to_string(negative) + " negative values set to 0 (after converting from " +
                               *from + ")");
    return img;
}

Result<bool> video_has_alpha(const std::string& path) {
    FfmpegVideo v;
    if (Status st = v.open(path, false); !st) return st.error();
    return v.has_alpha();
}

Result<io::SceneImage> first_scene_frame(const std::string& path, const io::SceneReadOptions& opts) {
    VideoReader r(path, io::FrameRange{});
    if (Status st = r.open(); !st) return st.error();
    long number = 0;
    cv::Mat frame;
    Result<bool> got = r.next(number, frame, r.deep());
    if (!got) return got.error();
    if (!*got) return make_error(Code::IoError, path + ": no frames to paint");
    return scene_from_frame(frame, r.has_alpha(), opts, path);
}

}  // namespace spt::video
