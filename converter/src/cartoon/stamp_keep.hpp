// Which old stamps a cartoon inter frame keeps: a rate-distortion rule on the decoder's
// rendering instead of a test on the source. A kept stamp costs no byte; a removed one costs
// its removal and, where it still helped, the new stamps that paint its error away again. So
// an old stamp stays while it still helps against the new frame: over the pixels it draws, the
// frame with the old stamps is no worse than the frame without them. Compressed video's noise
// changes the source under every stamp from frame to frame without changing what the stamps
// model (ringing and blur along the same edges), and the stamps stay; a stamp whose ground
// really changed (something moved over it, a vector moved it wrongly) now hurts and goes.
#pragma once

#include <cstdint>
#include <vector>

#include "paint/painter.hpp"
#include "spt/render.hpp"
#include "spt/types.hpp"

namespace spt::cartoon {

// `moved`: the old live list after this frame's move; `removed`: the indices the frame diff
// removes (increasing); `added`: the strokes the frame adds on top. Returns `removed` with the
// old stamps that do not help merged in (increasing).
std::vector<uint32_t> drop_unhelpful_stamps(const std::vector<Stroke>& moved, const std::vector<uint32_t>& removed,
                                            const std::vector<Stroke>& added, const paint::ImageView& model,
                                            const Renderer& renderer, const Header& header);

}  // namespace spt::cartoon
