// An OCIO display/view for scene-linear Rec.709 pixels, through OpenImageIO's colour
// management: what `spt render --view` applies before writing 8- or 16-bit images.
#pragma once

#include <memory>
#include <string>

#include "spt/result.hpp"

namespace spt::io {

struct ViewSpec {
    std::string view;     // the OCIO view, e.g. "ACES 1.0 - SDR Video"
    std::string display;  // empty: the config's default display
    std::string config;   // an OCIO config file; empty: $OCIO
};

class ViewTransform {
public:
    // Opens the config (io/color_config.hpp: --ocio, else $OCIO; the built-in config has no
    // views and is refused) and checks the display and view exist. The pixels are taken to be
    // linear Rec.709, what colour encoding 1 holds: the config's linear_rec709_space().
    static Result<std::unique_ptr<ViewTransform>> open(const ViewSpec& spec);
    virtual ~ViewTransform() = default;
    // In place: `n` straight (not premultiplied) RGB pixels, interleaved.
    virtual void apply(float* rgb, size_t n) const = 0;
    // "display/view from SPACE (config FILE)", for messages.
    virtual std::string description() const = 0;
};

}  // namespace spt::io
