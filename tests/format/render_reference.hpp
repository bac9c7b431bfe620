// What a frame must look like: strokes_at on a reader of its own, then Renderer::render (the
// reference the players' and render_frame's shortcuts are held to).
#pragma once

#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "spt/reader.hpp"
#include "spt/render.hpp"

namespace spt_test {

inline std::vector<uint8_t> reference_render(const std::vector<uint8_t>& file, size_t pos,
                                             const spt::ReaderOptions& o = {}) {
    auto r = spt::Reader::open_memory(file.data(), file.size(), o);
    EXPECT_TRUE(r.ok());
    if (!r.ok()) return {};
    auto live = (*r)->strokes_at(pos);
    EXPECT_TRUE(live.ok()) << live.error().message;
    if (!live.ok()) return {};
    auto rd = spt::Renderer::create((*r)->info().header, (*r)->info().templates);
    spt::Canvas c;
    EXPECT_TRUE((*rd)->render(c, **live).ok());
    return c.rgb;
}

}  // namespace spt_test
