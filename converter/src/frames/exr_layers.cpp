#include "frames/exr_layers.hpp"

#include <strings.h>

namespace spt::io {

namespace {

struct Layer {
    std::string name;
    int subimage = 0;
    std::vector<std::pair<std::string, int>> channels;  // own name, index in the subimage
};

std::string own_name(const std::string& channel) {
    const size_t dot = channel.rfind('.');
    return dot == std::string::npos ? channel : channel.substr(dot + 1);
}

std::vector<Layer> layers_of(const std::vector<ImagePart>& parts) {
    std::vector<Layer> out;
    for (size_t s = 0; s < parts.size(); ++s) {
        for (size_t c = 0; c < parts[s].channels.size(); ++c) {
            const std::string& ch = parts[s].channels[c];
            const std::string name = channel_layer(parts[s], int(s), ch);
            Layer* l = nullptr;
            for (Layer& x : out)
                if (x.subimage == int(s) && x.name == name) l = &x;
            if (!l) {
                out.push_back(Layer{name, int(s), {}});
                l = &out.back();
            }
            l->channels.emplace_back(own_name(ch), int(c));
        }
    }
    return out;
}

// The index of the channel called `want` (case-insensitive, one letter), or -1.
int find(const Layer& l, const char* want) {
    for (const auto& [n, i] : l.channels)
        if (strcasecmp(n.c_str(), want) == 0) return i;
    return -1;
}

bool has_rgb(const Layer& l) { return find(l, "R") >= 0 && find(l, "G") >= 0 && find(l, "B") >= 0; }

ChannelPick pick_layer(const Layer& l) {
    ChannelPick p;
    p.subimage = l.subimage;
    p.layer = l.name;
    p.color[0] = find(l, "R"), p.color[1] = find(l, "G"), p.color[2] = find(l, "B");
    p.alpha = find(l, "A");
    return p;
}

}  // namespace

std::string channel_layer(const ImagePart& part, int subimage, const std::string& channel) {
    const size_t dot = channel.rfind('.');
    if (dot != std::string::npos) return channel.substr(0, dot);
    if (subimage == 0) return {};
    return part.name.empty() ? "part " + std::to_string(subimage) : part.name;
}

std::string layers_text(const std::vector<ImagePart>& parts, size_t max_layers) {
    const std::vector<Layer> layers = layers_of(parts);
    std::string t;
    for (size_t i = 0; i < layers.size() && i < max_layers; ++i) {
        t += (i ? "; " : "") + (layers[i].name.empty() ? std::string("(unnamed)") : layers[i].name) + " ";
        for (size_t c = 0; c < layers[i].channels.size(); ++c) t += (c ? "," : "") + layers[i].channels[c].first;
    }
    if (layers.size() > max_layers) t += "; ... (" + std::to_string(layers.size()) + " layers in all)";
    return t.empty() ? std::string("no channels") : t;
}

Result<ChannelPick> pick_channels(const std::vector<ImagePart>& parts, const std::string& layer) {
    if (parts.empty() || parts[0].channels.empty()) return make_error(Code::Unsupported, "has no channels");
    const std::vector<Layer> layers = layers_of(parts);
    if (!layer.empty()) {
        for (const Layer& l : layers) {
            if (l.name != layer) continue;
            if (!has_rgb(l))
                return make_error(Code::InvalidArgument, "layer '" + layer + "' has no R, G, B channels (layers: " +
                                                             layers_text(parts) + ")");
            return pick_layer(l);
        }
        return make_error(Code::InvalidArgument, "has no layer '" + layer + "' (layers: " + layers_text(parts) + ")");
    }
    for (const Layer& l : layers)
        if (l.name.empty() && l.subimage == 0 && has_rgb(l)) return pick_layer(l);
    for (const Layer& l : layers)
        if (has_rgb(l)) return pick_layer(l);

    // No R, G, B by name: channels by position, as PNG, JPEG and TIFF readers order them.
    const ImagePart& p = parts[0];
    const int n = int(p.channels.size());
    bool layered = false;
    for (const std::string& c : p.channels) layered = layered || c.find('.') != std::string::npos;
    ChannelPick pick;
    std::string names;
    for (const std::string& c : p.channels) names += (names.empty() ? "" : ", ") + c;
    if (n <= 2) {
        pick.gray = true;
        pick.color[0] = pick.color[1] = pick.color[2] = 0;
        if (n == 2) pick.alpha = 1;
        // A grey image names its channels Y (and A); anything else is not one (a depth pass,
        // a matte, two colour channels) and is painted as grey only by position: said.
        const bool grey = p.channels[0] == "Y" && (n == 1 || p.channels[1] == "A");
        if (!grey)
            pick.warning = "has no R, G, B channels (channels: " + names + "): painted as grey from " + p.channels[0] +
                           (n == 2 ? " with " + p.channels[1] + " as alpha" : "");
        return pick;
    }
    if (layered)
        return make_error(Code::Unsupported, "has no R, G, B channels (layers: " + layers_text(parts) +
                                                 "): name the layer to paint with --layer");
    if (p.alpha_channel >= 3) pick.alpha = p.alpha_channel;
    else if (n == 4 && p.alpha_channel < 0) pick.alpha = 3;
    pick.warning = "has no R, G, B channels (channels: " + names + "): painted as R, G, B from " + p.channels[0] + ", " +
                   p.channels[1] + ", " + p.channels[2] + (pick.alpha >= 0 ? " with " + p.channels[size_t(pick.alpha)] + " as alpha" : "");
    return pick;
}

}  // namespace spt::io
