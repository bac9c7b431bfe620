// The list of importers, format detection, sequences of files.
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <regex>

#include "spt_import/importer.hpp"

namespace spt::import {

// Each importer module defines one of these. To add an importer: a new .cpp and a line here.
extern const Importer kStrokesJsonImporter;
extern const Importer kGeometrizeJsonImporter;
extern const Importer kSvgImporter;
extern const Importer kLottieImporter;

const std::vector<const Importer*>& importers() {
    static const std::vector<const Importer*> list = {&kStrokesJsonImporter, &kGeometrizeJsonImporter, &kLottieImporter, &kSvgImporter};
    return list;
}

const Importer* find_importer(std::string_view name) {
    for (const Importer* i : importers())
        if (name == i->name) return i;
    return nullptr;
}

const Importer* detect_importer(const std::string& path, std::string_view head) {
    for (const Importer* i : importers())
        if (i->sniff(path, head)) return i;
    return nullptr;
}

Result<std::string> read_file(const std::string& path, size_t max_bytes) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) return make_error(Code::InvalidArgument, path + ": is a folder");
    std::ifstream in(path, std::ios::binary);
    if (!in) return make_error(Code::IoError, path + ": cannot open for reading");
    in.seekg(0, std::ios::end);
    const auto size = in.tellg();
    if (size < 0) return make_error(Code::IoError, path + ": cannot determine the size");
    if (uint64_t(size) > max_bytes)
        return make_error(Code::LimitExceeded, path + ": " + std::to_string(uint64_t(size)) + " bytes is above the " +
                                                   std::to_string(max_bytes) + "-byte input limit");
    in.seekg(0);
    std::string s(size_t(size), '\0');
    if (!in.read(s.data(), size)) return make_error(Code::IoError, path + ": read failed");
    return s;
}

namespace {

// Splits a pattern around its frame placeholder: "a.####.svg" / "a.%04d.svg" / "a.#.svg".
bool split_pattern(const std::string& name, std::string& prefix, std::string& suffix, int& digits) {
    static const std::regex printf_re("%0?([0-9]*)d");
    std::smatch m;
    if (std::regex_search(name, m, printf_re)) {
        prefix = m.prefix();
        suffix = m.suffix();
        // A width of more than two digits matches no file name (and would overflow stoi).
        digits = m[1].length() == 0 ? 0 : m[1].length() <= 2 ? std::stoi(m[1]) : 100;
        return true;
    }
    auto a = name.find('#');
    if (a == std::string::npos) return false;
    auto b = name.find_first_not_of('#', a);
    if (b == std::string::npos) b = name.size();
    prefix = name.substr(0, a);
    suffix = name.substr(b);
    digits = int(b - a);
    return true;
}

}  // namespace

Result<std::vector<std::string>> expand_inputs(const std::string& path) {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<std::string> out;
    if (fs::is_directory(path, ec)) {
        for (const auto& e : fs::directory_iterator(path, ec)) {
            if (!e.is_regular_file()) continue;
            std::string ext = e.path().extension().string();
            std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
            if (ext == ".svg" || ext == ".json") out.push_back(e.path().string());
        }
        if (ec) return make_error(Code::IoError, path + ": cannot list the folder");
        std::sort(out.begin(), out.end());
        if (out.empty()) return make_error(Code::InvalidArgument, path + ": no .svg or .json files in the folder");
        return out;
    }
    const fs::path p(path);
    const std::string name = p.filename().string();
    std::string prefix, suffix;
    int digits = 0;
    if (fs::exists(p, ec) || !split_pattern(name, prefix, suffix, digits)) {
        if (!fs::exists(p, ec)) return make_error(Code::IoError, path + ": no such file");
        return std::vector<std::string>{path};
    }
    const fs::path dir = p.has_parent_path() ? p.parent_path() : fs::path(".");
    std::vector<std::pair<long, std::string>> found;
    for (const auto& e : fs::directory_iterator(dir, ec)) {
        const std::string n = e.path().filename().string();
        if (n.size() <= prefix.size() + suffix.size() || n.compare(0, prefix.size(), prefix) != 0 ||
            n.compare(n.size() - suffix.size(), suffix.size(), suffix) != 0)
            continue;
        const std::string num = n.substr(prefix.size(), n.size() - prefix.size() - suffix.size());
        if (num.empty() || num.size() > 9 || !std::all_of(num.begin(), num.end(), [](unsigned char c) { return std::isdigit(c); })) continue;
        if (digits > 1 && int(num.size()) != digits) continue;
        found.emplace_back(std::stol(num), e.path().string());
    }
    if (found.empty()) return make_error(Code::IoError, path + ": no file matches the sequence pattern");
    std::sort(found.begin(), found.end());
    for (auto& f : found) out.push_back(std::move(f.second));
    return out;
}

Result<Document> import_path(const std::string& path, const std::string& from, const ImportOptions& opts) {
    const Importer* forced = nullptr;
    if (!from.empty()) {
        forced = find_importer(from);
        if (!forced) return make_error(Code::InvalidArgument, "unknown importer '" + from + "'");
    }
    auto files = expand_inputs(path);
    if (!files) return files.error();
    if (files->size() > opts.limits.max_frames) return make_error(Code::LimitExceeded, path + ": too many files");
    Document out;
    std::vector<std::vector<Stroke>> lists;
    for (size_t i = 0; i < files->size(); ++i) {
        const std::string& f = (*files)[i];
        auto text = read_file(f, opts.max_file_bytes);
        if (!text) return text.error();
        const Importer* imp = forced ? forced : detect_importer(f, std::string_view(*text).substr(0, 4096));
        if (!imp) return make_error(Code::Unsupported, f + ": format not recognised (use --from spt-json, geometrize-json, lottie or svg)");
        auto doc = imp->load(f, std::move(*text), opts);
        if (!doc) return doc.error();
        if (files->size() == 1) return doc;
        // A sequence: every file must be a single frame on the same canvas and templates.
        if (doc->frames.size() != 1) return make_error(Code::InvalidArgument, f + ": a sequence member must hold exactly one frame");
        if (i == 0) {
            out.info = doc->info;
        } else {
            const Header& a = out.info.header;
            const Header& b = doc->info.header;
            if (a.width != b.width || a.height != b.height)
                return make_error(Code::InvalidArgument, f + ": canvas " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                                                             " differs from the first file's " + std::to_string(a.width) + "x" + std::to_string(a.height));
            if (!(out.info.templates == doc->info.templates))
                return make_error(Code::InvalidArgument, f + ": templates differ from the first file's");
        }
        lists.push_back(std::move(doc->frames[0].added));
        out.report.merge(doc->report);
        out.canvas_strips = out.canvas_strips || doc->canvas_strips;
    }
    out.frames = frames_from_lists(lists);
    out.info.header.frame_count = uint32_t(out.frames.size());
    return out;
}

}  // namespace spt::import
