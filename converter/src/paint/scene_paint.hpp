// Painting render output (format 1.3, issue 17): a scene-linear RGBA image painted onto an
// alpha canvas and/or in colour encoding 1. The painter paints the 8-bit proxy of
// linear_proxy.hpp (for an sRGB8 file: the sRGB image itself, premultiplied) with the exact
// RGBA model of painter.hpp; a linear file then gets its colours from linear_refit.hpp.
#pragma once

#include "paint/linear_proxy.hpp"
#include "paint/linear_refit.hpp"
#include "paint/painter.hpp"
#include "spt/result.hpp"

namespace spt::paint {

struct SceneTarget {
    bool alpha = false;   // an alpha canvas (HEAD flag alpha)
    bool linear = false;  // colour encoding 1 (scene-linear half codes)
    RefitOptions refit;
};

struct ScenePainting {
    Header header;               // the file's header
    std::vector<Stroke> strokes; // in the file's colour encoding
    Canvas canvas;               // Renderer::render of `strokes` under `header`
    ProxyTransform transform;    // what the proxy was (peak 1 for sRGB8 files)
    PaintStats stats;            // of the proxy paint (its PSNR is the proxy's, RGB(A))
    RefitStats refit;
};

// `setup` is a plain still setup (make_setup: sizes, sets, templates; its background the 8-bit
// sRGB colour a viewer shows). The proxy's peak is `peak` when > 0, else the image's.
Result<ScenePainting> paint_scene(const LinearView& img, const PaintSetup& setup, const PaintOptions& opts,
                                  const SceneTarget& target, double peak = 0, const PaintProgressFn& progress = {});

// True when some pixel is not fully opaque: an alpha channel that is 1 everywhere (an RGBA
// PNG of an opaque picture) asks for no alpha canvas under "--alpha auto".
bool has_transparency(const LinearView& img);

// The share of pixels that are partly transparent (alpha 16/255 .. 239/255: not an edge's
// few pixels nor a matte's). Stamps composite over (SPEC.md 8.6) and only ever raise alpha, so
// the stamp painter cannot put detail inside such an area without making it more opaque than
// the source: every stroke it could add costs more alpha error than it gains in colour.
double partial_alpha_share(const LinearView& img);

// The header a SceneTarget gives a plain setup header (background converted for linear files).
Header scene_header(const Header& plain, const SceneTarget& target);

}  // namespace spt::paint
