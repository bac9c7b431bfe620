// libspt: reads, writes and renders .spt files (format/SPEC.md), standard library only.
//
// A .spt file is a header (canvas size, frame rate, stroke sets, orientation table), a few
// templates (the shapes strokes are made of), and frames. A key frame holds the whole list of
// live strokes; an inter frame edits the list before it (removals, a motion field, strokes
// added on top). Rendering a frame draws its live strokes in order onto the background, with
// integer arithmetic only: every conforming decoder produces the same bytes.
//
// The headers, and what each is for:
//   spt/types.hpp    the data model: Header, Template, Stroke (stamp, affine, curve, polygon),
//                    Frame, StreamInfo
//   spt/writer.hpp   Writer: append frames with constant memory, finish() writes the index
//   spt/reader.hpp   Reader: open a file or buffer, seek to any frame, its live strokes, or
//                    render_frame() (a player's call); apply_frame() (the state update)
//   spt/render.hpp   Canvas and Renderer: strokes to RGB8 pixels, bit-exactly
//   spt/display.hpp  a canvas of any kind as straight sRGB RGBA for a screen (viewers)
//   spt/coding.hpp   Coding (how frame bodies are coded) and per-field bit counts
//   spt/replay.hpp   the candidate generator of frame coding 2, for painters that want their
//                    frames coded by which candidates they accepted
//   spt/limits.hpp   Limits: what a Reader accepts before it allocates (hostile input)
//   spt/result.hpp   Status, Result<T>, Error: every call that can fail says why
//   spt/version.hpp  library and format versions
//   spt/color.hpp    colour encoding 1 (scene-linear half floats): SPEC.md 8.6's conversions
//   spt/utf8.hpp     UTF-8 validation for the text the format carries (the Writer refuses
//                    metadata that is not UTF-8; a tool checks its input with the same rule)
// Supported API as well, included on their own (tools, not every reader needs them):
//   spt/concat.hpp       join .spt files without re-coding (SPEC.md 9.6; farm shots)
//   spt/atomic_file.hpp  outputs that appear only when complete and follow no symlink (the
//                        Writer's own; the converter, importers and farm write through it too)
// Every header here is standard C++20 with no compiler extension (tests/format checks it with
// g++ and clang++ -Wpedantic -Werror, and that this list names every header).
//
// Errors are values: a Result<T> is either a T or an Error (code, message naming the file,
// frame and byte offset); nothing throws on bad input. A Reader checks every count against
// Limits before allocating and every frame's CRC before decoding it.
//
// Example: write a key frame and an inter frame, read the file back, seek to the second frame
// and render it (this program is built and run by tests/consumer against the installed library):
//
// ---- example begin
// #include <cstdio>
// #include <spt/spt.hpp>
//
// int main(int argc, char** argv) {
//     if (argc != 2) return 2;
//     const char* path = argv[1];
//
//     // A 64 x 48 canvas with one stroke set of 16 x 8 px stamps, 8 orientations and one
//     // template, an analytic ellipse.
//     spt::StreamInfo info;
//     info.header.width = 64;
//     info.header.height = 48;
//     info.header.sets = {{16, 8}};
//     info.header.orientations = spt::default_orientations(8);
//     spt::Template ellipse;
//     ellipse.kind = spt::TemplateKind::Ellipse;
//     info.templates = {ellipse};
//
//     // Write: a key frame of two stamps, then an inter frame that removes the first stamp and
//     // adds a third. Positions are in 1/16 pixel; 16 * x + 8 is the centre of pixel x.
//     auto writer = spt::Writer::create(path, info);
//     if (!writer) return std::fprintf(stderr, "%s\n", writer.error().message.c_str()), 1;
//     auto stamp = [](int x, int y, uint8_t orient, spt::Rgba8 color) {
//         spt::StampStroke s;
//         s.orient = orient;
//         s.x = 16 * x + 8;
//         s.y = 16 * y + 8;
//         s.color = color;
//         return spt::Stroke::make_stamp(s);
//     };
//     spt::Frame key;
//     key.index = 0;
//     key.type = spt::FrameType::Key;
//     key.added = {stamp(20, 20, 0, {200, 30, 30, 255}), stamp(40, 30, 2, {30, 30, 200, 255})};
//     spt::Frame inter;
//     inter.index = 1;
//     inter.type = spt::FrameType::Inter;
//     inter.removed = {0};
//     inter.added = {stamp(32, 24, 4, {30, 160, 30, 128})};
//     for (const spt::Frame* f : {&key, &inter})
//         if (auto st = (*writer)->append(*f); !st) return std::fprintf(stderr, "%s\n", st.error().message.c_str()), 1;
//     if (auto st = (*writer)->finish(); !st) return std::fprintf(stderr, "%s\n", st.error().message.c_str()), 1;
//
//     // Read: open, seek to frame 1 (decoded from the key frame before it), render it.
//     auto reader = spt::Reader::open(path);
//     if (!reader) return std::fprintf(stderr, "%s\n", reader.error().message.c_str()), 1;
//     spt::Reader& r = **reader;
//     auto live = r.strokes_at(1);
//     if (!live) return std::fprintf(stderr, "%s\n", live.error().message.c_str()), 1;
//     spt::Canvas canvas;
//     if (auto st = r.render_frame(1, canvas); !st) return std::fprintf(stderr, "%s\n", st.error().message.c_str()), 1;
//
//     // The same pixels from a Renderer of the file's header and templates.
//     auto renderer = spt::Renderer::create(r.info().header, r.info().templates);
//     if (!renderer) return std::fprintf(stderr, "%s\n", renderer.error().message.c_str()), 1;
//     spt::Canvas again;
//     if (auto st = (*renderer)->render(again, **live); !st) return std::fprintf(stderr, "%s\n", st.error().message.c_str()), 1;
//
//     const uint8_t* centre = canvas.row(24) + 3 * 32;  // the half-transparent green stamp
//     std::printf("%zu frames, %zu live strokes in frame 1, centre pixel %u %u %u, %s\n", r.frames().size(),
//                 (*live)->size(), centre[0], centre[1], centre[2], again.rgb == canvas.rgb ? "same pixels" : "DIFFERENT");
//     return (*live)->size() == 2 && again.rgb == canvas.rgb ? 0 : 1;
// }
// ---- example end
#pragma once

#include "spt/color.hpp"
#include "spt/coding.hpp"
#include "spt/display.hpp"
#include "spt/limits.hpp"
#include "spt/reader.hpp"
#include "spt/render.hpp"
#include "spt/replay.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"
#include "spt/utf8.hpp"
#include "spt/version.hpp"
#include "spt/writer.hpp"
