// Loads a folder of the user's own stroke templates (paper: "any 60x60 pixel grayscale image as
// a stroke template"): every image file of the folder, in name order, as a bitmap template.
#pragma once

#include <string>
#include <vector>

#include "spt/result.hpp"
#include "spt/types.hpp"

namespace spt::io {

// Image files are recognised by extension (.png .tif .tiff .jpg .jpeg .bmp .pgm .exr .webp);
// other files are ignored. One channel is taken as coverage (0 none .. 255 full); gray+alpha
// uses the gray channel; RGB(A) is converted to Rec.709 luma. Any size from 1x1 to 1024x1024
// (60x60 is the convention). Errors name the folder or the file: a missing folder, no image in
// it, an unreadable or oversized image, more than 255 templates, or a template with no
// coverage at all (it could never paint anything).
Result<std::vector<Template>> load_templates(const std::string& dir);

}  // namespace spt::io
