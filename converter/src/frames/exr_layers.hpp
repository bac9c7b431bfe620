// Which channels of a multi-channel image are its colour and alpha: EXRs from renderers hold
// layers ("ViewLayer.Combined.R", "ViewLayer.Depth.Z", ...), in one part or in several.
#pragma once

#include <string>
#include <vector>

#include "spt/result.hpp"

namespace spt::io {

// The channels of one subimage (an EXR part) as OpenImageIO lists them.
struct ImagePart {
    std::string name;                   // the part name (oiio:subimagename), may be empty
    std::vector<std::string> channels;
    int alpha_channel = -1;             // ImageSpec::alpha_channel
};

struct ChannelPick {
    int subimage = 0;
    int color[3] = {0, 1, 2};  // channel indices in that subimage; all equal for gray
    int alpha = -1;            // -1: none
    bool gray = false;
    std::string layer;         // "" for the unnamed layer
    // Set when channels were taken by position from a file whose names say they are not a
    // picture's (only Z, only A, R and G): what was painted from what, for a warning.
    std::string warning;
};

// The layer of a channel name (before the last '.') and its own name (after it). Channels of a
// part after the first with no '.' belong to the part's name as a layer.
std::string channel_layer(const ImagePart& part, int subimage, const std::string& channel);

// `layer` non-empty: that layer's R, G, B (and A when present), an error listing the layers
// found when there is no such layer. Empty: the unnamed layer's R, G, B (A), else the first
// layer that has R, G, B; files without channel names in layers (PNG, TIFF) by position: 1
// channel gray, 2 gray + alpha, 3+ RGB then the alpha channel. Messages do not name the file.
Result<ChannelPick> pick_channels(const std::vector<ImagePart>& parts, const std::string& layer);

// "(unnamed) R,G,B,A; ViewLayer.Combined R,G,B,A; ViewLayer.Depth Z" for messages.
std::string layers_text(const std::vector<ImagePart>& parts, size_t max_layers = 12);

}  // namespace spt::io
