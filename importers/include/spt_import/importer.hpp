// The importer interface and registry. Each importer is one small module (a .cpp defining one
// `Importer` value); adding one means a new file and one line in registry.cpp.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "spt/limits.hpp"
#include "spt_import/document.hpp"

namespace spt::import {

struct ImportOptions {
    Limits limits;
    std::optional<Rgb8> background;  // overrides the source's canvas colour
    std::optional<Rational> fps;     // overrides the source's frame rate
    // Canvas size for sources that do not state one (geometrize JSON without a background
    // rectangle); `spt import` takes it from --size or from the --reference image.
    std::optional<std::pair<uint32_t, uint32_t>> canvas_size;
    size_t max_file_bytes = size_t(256) << 20;
};

struct Importer {
    const char* name;         // for --from
    const char* description;  // one line for --help
    // True when the file looks like this importer's format (extension and first bytes).
    bool (*sniff)(const std::string& path, std::string_view head);
    // Loads one file. `text` is its whole content, handed over so that a parser may work in
    // place (the SVG importer does: no second copy of a large file); `path` names it in errors.
    Result<Document> (*load)(const std::string& path, std::string text, const ImportOptions& opts);
};

const std::vector<const Importer*>& importers();
const Importer* find_importer(std::string_view name);
// The first importer whose sniff accepts the file, or nullptr.
const Importer* detect_importer(const std::string& path, std::string_view head);

// Imports a file, a numbered sequence ("shapes.####.svg", "frame_%04d.json") or a folder of
// files (name order): one frame per file, consecutive files sharing a prefix of strokes become
// inter frames. `from` forces an importer by name (empty: detect per file).
Result<Document> import_path(const std::string& path, const std::string& from, const ImportOptions& opts = {});

// The files of a sequence pattern or folder, in frame order; a plain file gives itself.
Result<std::vector<std::string>> expand_inputs(const std::string& path);

// Reads a file whole, refusing files above `max_bytes`.
Result<std::string> read_file(const std::string& path, size_t max_bytes);

}  // namespace spt::import
