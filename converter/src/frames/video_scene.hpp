// A decoded video frame as the scene-linear reader gives an image (io/scene_image.hpp): what
// the painter paints an alpha canvas (or colour encoding 1) from when the video file holds
// alpha (ProRes 4444, VP9 WebM alpha, PNG in MOV) or is painted with --color-encoding linear.
#pragma once

#include <string>

#include <opencv2/core.hpp>

#include "frames/scene_image.hpp"
#include "spt/result.hpp"

namespace spt::video {

// `frame`: 8-bit BGR or 16-bit RGBA (straight alpha, as video codecs store it), in the colour
// space `opts.colorspace` names (empty: sRGB). Converted to linear Rec.709 through the same
// OCIO config and transforms as an image file, then premultiplied. `alpha`: the file has an
// alpha channel (else alpha is 1 and has_alpha false); `depth`: the source's bits a sample.
// Errors name `path`.
Result<io::SceneImage> scene_from_frame(const cv::Mat& frame, bool alpha, int depth, const io::SceneReadOptions& opts,
                                        const std::string& path);

// Whether a video file's stream holds alpha (read from its header; nothing is decoded).
Result<bool> video_has_alpha(const std::string& path);
// Frame 0 of a video file through scene_from_frame: what decides --alpha auto for it, as the
// first file of a sequence does.
Result<io::SceneImage> first_scene_frame(const std::string& path, const io::SceneReadOptions& opts);

}  // namespace spt::video
