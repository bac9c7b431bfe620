// A small OCIO config of the kind a studio gives: lin_rec709 as reference, ACEScg through
// OCIO's own built-in AP1 -> Rec.709 transform (so expected values do not come from our code), an
// sRGB texture space; aliases as real configs have them.
#pragma once

#include <fstream>
#include <string>

namespace spt_test {

inline std::string write_studio_ocio(const std::string& path) {
    std::ofstream f(path);
    f << R"(ocio_profile_version: 2
roles:
  default: lin_rec709
  reference: lin_rec709
  scene_linear: ACEScg
file_rules:
  - !<Rule> {name: Default, colorspace: default}
displays:
  sRGB:
    - !<View> {name: Raw, colorspace: lin_rec709}
colorspaces:
  - !<ColorSpace>
    name: lin_rec709
    aliases: [Linear Rec.709 (sRGB)]
    encoding: scene-linear
  - !<ColorSpace>
    name: ACEScg
    aliases: [ACES - ACEScg, lin_ap1]
    encoding: scene-linear
    to_scene_reference: !<BuiltinTransform> {style: "UTILITY - ACES-AP1_to_LINEAR-REC709_BFD"}
  - !<ColorSpace>
    name: srgb_tx
    aliases: [sRGB - Texture]
    encoding: sdr-video
    from_scene_reference: !<ExponentWithLinearTransform> {gamma: 2.4, offset: 0.055, direction: inverse}
)";;
    return path;
}

}  // namespace spt_test
