// Rendering an imported document and matching it to the painting tool's own rendering.
#pragma once

#include <cstdint>

#include "spt/render.hpp"
#include "spt/result.hpp"
#include "spt_import/document.hpp"

namespace spt::import {

// The frame at position `frame` rendered with spt::Renderer.
Result<Canvas> render_frame(const Document& doc, size_t frame);

// The canvas colour that makes the last frame closest (least squares) to `reference`
// (width x height RGB8): the rendering is, per pixel, affine in the background colour, with
// the weight the strokes leave it (their product of 1 - alpha).
Result<Rgb8> fit_background(const Document& doc, const uint8_t* reference);

// PSNR in dB over R, G, B (peak 255); +infinity for identical images.
double psnr_rgb8(const uint8_t* a, const uint8_t* b, size_t pixels);

}  // namespace spt::import
