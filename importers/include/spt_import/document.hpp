// What an importer produces: everything a .spt file holds, as values.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "spt/limits.hpp"
#include "spt/result.hpp"
#include "spt/types.hpp"
#include "spt/writer.hpp"

namespace spt::import {

// Notes on how faithful an import is: shapes the stroke model could only approximate.
struct ImportReport {
    uint64_t shapes = 0;          // shapes read
    uint64_t strokes = 0;         // strokes written
    uint64_t approximated = 0;    // shapes not exact up to the Q4 grid (split polygons, curves...)
    uint64_t dropped = 0;         // shapes that cover nothing (degenerate, fully transparent)
    double max_q4_error_px = 0;   // largest vertex displacement from rounding to 1/16 px
    std::vector<std::string> notes;  // human-readable, one per kind of approximation
    // False when the source does not state the canvas colour (geometrize JSON without its
    // background rectangle, SVG without a background rect): `spt import --reference` fits it.
    bool background_stated = true;
    void note(const std::string& n);  // adds once
    void merge(const ImportReport& o);
};

struct Document {
    StreamInfo info;
    std::vector<Frame> frames;  // as stored: key frames and inter frames
    ImportReport report;
    // Strokes painted in the canvas colour (geometrize never paints the last row and column:
    // opaque rectangles put the canvas colour back there). set_background() recolours them.
    bool canvas_strips = false;
};

// The two opaque rectangles (last column, then last row without its last pixel) that paint
// the canvas colour back where geometrize never draws.
std::vector<Stroke> canvas_strip_strokes(uint32_t width, uint32_t height, Rgb8 colour, uint8_t rectangle_template);
// Sets the canvas colour, and the colour of the canvas strips when the document has them.
void set_background(Document& doc, Rgb8 colour);

// The templates used when a source names none: ellipse, rectangle, triangle (ids 0, 1, 2).
std::vector<Template> default_templates();
// A header with the given canvas and the default set/orientation tables.
Header default_header(uint32_t width, uint32_t height, Rgb8 background);

// Drops what a document of shapes does not use, so that small files stay small: templates no
// stroke refers to (the others renumbered in order), and, when no frame has a stamp stroke, all
// but one entry of the orientation table (stamps are the only strokes that read it).
void drop_unused_tables(Document& doc);

// Builds stored frames from per-frame stroke lists: the first is a key frame; each next one is
// an inter frame that removes the tail of the previous list not shared as a common prefix and
// appends the rest, unless that costs more strokes than a key frame.
std::vector<Frame> frames_from_lists(const std::vector<std::vector<Stroke>>& lists);

// Checks what the writer would reject, with readable messages naming `source`: header values,
// template ids and stroke value ranges (SPEC.md section 4), counts against `limits`.
Status validate(const Document& doc, const std::string& source, const Limits& limits = {});

// Writes a document (atomic: nothing is left at `path` on failure).
Result<WriteStats> write_document(const Document& doc, const std::string& path, const WriterOptions& opts = {});

// Reads a whole .spt file into a document (frames as stored).
Result<Document> read_document(const std::string& path, const Limits& limits = {});

// The live stroke list after each frame (applies frames in order).
Result<std::vector<std::vector<Stroke>>> live_lists(const Document& doc);

}  // namespace spt::import
