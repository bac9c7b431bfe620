// How frame bodies are coded (SPEC.md 6 and 7), and where their bits go per field: shared by
// the writer (which chooses a coding) and the reader (which reports the coding of each frame).
#pragma once

#include <cstddef>
#include <cstdint>

namespace spt {

enum class Coding : uint8_t {
    Stored = 0,   // fixed-size little-endian fields, no entropy coding (SPEC.md "Stored frames")
    Range = 1,    // context-adaptive binary range coding (SPEC.md "Range-coded frames")
    // Decoder-replayed candidates (SPEC.md 7.7): frames whose Frame::replay describes how their
    // stamps were drawn code accept gaps instead of positions, colours and orientations against
    // the canvas painted so far; any other frame falls back to coding 1.
    Replay = 2,
};
// "stored", "range", "replay"; "reserved" for any other value.
const char* coding_name(Coding c);

// Where the bits of frame bodies go, per field (for `spt info` and benches). Stored coding
// counts exact bytes; range coding counts the information cost -log2(p) of every coded
// decision of the field, which sums to the stream size within a few bytes per frame.
enum class Field : uint8_t {
    Count = 0,    // frame-level counts and sizes (stroke/removal counts, stream lengths)
    Kind,         // stroke kind
    SetTemplate,  // stamp set, template of any stroke
    Orientation,  // stamp orientation
    Position,     // stamp/affine anchor, first curve point
    Color,        // R, G, B
    Alpha,        // A
    Geometry,     // affine matrix, curve point count, further curve points, widths
    Removal,      // removed stroke indices
    Motion,       // motion field
    Candidates,   // coding 2: accepted-candidate gaps, per-set counts, candidate regions, seed
};
constexpr size_t kFieldCount = 11;
const char* field_name(Field f);

struct FieldStats {
    double bits[kFieldCount] = {};
    double& operator[](Field f) { return bits[size_t(f)]; }
    double operator[](Field f) const { return bits[size_t(f)]; }
    double bytes(Field f) const { return bits[size_t(f)] / 8.0; }
    double total_bits() const { double t = 0; for (double b : bits) t += b; return t; }
    void add(const FieldStats& o) { for (size_t i = 0; i < kFieldCount; ++i) bits[i] += o.bits[i]; }
};

}  // namespace spt
