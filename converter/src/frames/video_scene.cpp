#include "frames/video_scene.hpp"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>
#include <opencv2/imgproc.hpp>

#include "io/color_config.hpp"
#include "frames/ffmpeg_video.hpp"
#include "frames/video_reader.hpp"

namespace spt::video {

Result<io::SceneImage> scene_from_frame(const cv::Mat& frame, bool alpha, int depth, const io::SceneReadOptions& opts,
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
    // Samples to float as OpenImageIO converts an image file's (8-bit sources at 8 bits, so an
    // 8-bit video with alpha reads as a PNG of its frame does).
    cv::Mat rgba;
    if (frame.depth() == CV_16U) rgba = frame;
    else cv::cvtColor(frame, rgba, cv::COLOR_BGR2RGBA);
    if (rgba.depth() == CV_16U && depth <= 8) rgba.convertTo(rgba, CV_8U, 255.0 / 65535.0);
    const OIIO::TypeDesc type = rgba.depth() == CV_16U ? OIIO::TypeDesc::UINT16 : OIIO::TypeDesc::UINT8;
    OIIO::ImageSpec src_spec(rgba.cols, rgba.rows, 4, type);
    OIIO::ImageBuf src(src_spec, rgba.data, OIIO::AutoStride, OIIO::stride_t(rgba.step[0]));
    if (!src.get_pixels(OIIO::ROI(0, rgba.cols, 0, rgba.rows, 0, 1, 0, 4), OIIO::TypeDesc::FLOAT, img.rgba.data()))
        return make_error(Code::Unsupported, path + ": cannot convert a frame's samples: " + src.geterror());
    if (!alpha)
        for (size_t i = 3; i < img.rgba.size(); i += 4) img.rgba[i] = 1.f;
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
    return scene_from_frame(frame, r.has_alpha(), r.bit_depth(), opts, path);
}

}  // namespace spt::video
