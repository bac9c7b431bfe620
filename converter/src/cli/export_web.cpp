// spt export -o page.html / -o folder/ --web (see export_web.hpp). The player's files are
// compiled into spt (web/src/web_assets.hpp): the page is made from the very player and libspt
// build that this spt carries, with nothing to locate at run time.
#include "cli/export_web.hpp"

#include <OpenImageIO/strutil.h>
#include <zlib.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string_view>
#include <system_error>

#include "cli/commands.hpp"
#include "io/spt_file.hpp"
#include "spt_import/export.hpp"
#include "web_assets.hpp"

namespace spt::cli {

namespace fs = std::filesystem;

namespace {

int fail(const std::string& msg) { return command_failed("export", msg); }

bool ends_with_ci(std::string s, std::string_view suffix) {
    for (auto& c : s) c = char(std::tolower((unsigned char)c));
    return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

std::string_view asset(std::string_view name) {
    for (const auto& a : web::player_assets())
        if (a.name == name) return a.bytes;
    return {};
}

std::string html_escape(std::string_view s) {
    std::string o;
    for (char c : s) {
        if (c == '&') o += "&amp;";
        else if (c == '<') o += "&lt;";
        else if (c == '>') o += "&gt;";
        else if (c == '"') o += "&quot;";
        else o += c;
    }
    return o;
}

// JavaScript inside <script>: a "</script" in it would end the element early.
std::string script_safe(std::string_view js) {
    std::string o(js);
    for (size_t p = 0; (p = o.find("</script", p)) != std::string::npos; p += 2) o.replace(p, 2, "<\\/");
    return o;
}

const char* kPageStyle =
    "html,body{margin:0;height:100%;background:#111}"
    "body{display:flex;align-items:center;justify-content:center}";

std::string page_head(const std::string& title) {
    return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
           "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n<title>" +
           html_escape(title) + "</title>\n<style>" + kPageStyle + "</style>\n";
}

// `data` as a gzip stream (what the browser's DecompressionStream("gzip") inflates); empty if
// zlib fails.
std::string gzip(std::string_view data) {
    z_stream z{};
    if (deflateInit2(&z, 9, Z_DEFLATED, 15 + 16, 9, Z_DEFAULT_STRATEGY) != Z_OK) return {};
    std::string out(deflateBound(&z, uLong(data.size())), '\0');
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data.data()));
    z.avail_in = uInt(data.size());
    z.next_out = reinterpret_cast<Bytef*>(out.data());
    z.avail_out = uInt(out.size());
    const int rc = deflate(&z, Z_FINISH);
    out.resize(z.total_out);
    deflateEnd(&z);
    return rc == Z_STREAM_END ? out : std::string();
}

// The clip as an inert <script> element: gzipped when that saves a tenth (stored-mode clips
// shrink several times; range-coded ones hardly at all).
std::string clip_element(const std::string& clip) {
    const std::string z = gzip(clip);
    const bool packed = !z.empty() && z.size() < clip.size() - clip.size() / 10;
    return std::string("<script type=\"application/octet-stream\" id=\"spt-clip\"") +
           (packed ? " data-encoding=\"gzip\">" : ">") + OIIO::Strutil::base64_encode(packed ? z : clip) + "</script>\n";
}

// One page: the clip and the gzipped module as base64 text in inert <script> elements, and the
// two ES modules joined into one inline module (the player's import of spt-core.js dropped).
std::string self_contained_page(const std::string& title, const std::string& clip) {
    std::string player(asset("spt-player.js"));
    const std::string import_line = "import { loadSptCore, SptError } from './spt-core.js';\n";
    if (size_t p = player.find(import_line); p != std::string::npos) player.erase(p, import_line.size());
    std::string page = page_head(title) + "</head>\n<body>\n<spt-player src=\"#spt-clip\" autoplay loop></spt-player>\n";
    page += clip_element(clip);
    page += "<script type=\"application/octet-stream\" id=\"spt-player-wasm\" data-encoding=\"gzip\">" +
            OIIO::Strutil::base64_encode(asset("spt_core.wasm.gz")) + "</script>\n";
    page += "<script type=\"module\">\n" + script_safe(asset("spt-core.js")) + "\n" + script_safe(player) + "</script>\n";
    return page + "</body>\n</html>\n";
}

std::string hosted_page(const std::string& title, const std::string& clip_name) {
    return page_head(title) + "<script type=\"module\" src=\"spt-player.js\"></script>\n</head>\n<body>\n"
           "<spt-player src=\"" + html_escape(clip_name) + "\" autoplay loop></spt-player>\n</body>\n</html>\n";
}

}  // namespace

bool is_web_export(const std::string& out, bool web_flag) {
    return web_flag || ends_with_ci(out, ".html") || ends_with_ci(out, ".htm");
}

int export_web(const std::string& in, const std::string& out, bool folder) {
    // The file first (what spt verify checks: the page plays every frame), then the player.
    auto reader = io::open_spt(in);
    if (!reader) return fail(reader.error().message);
    Reader& r = **reader;
    std::vector<size_t> every(r.frames().size());
    for (size_t i = 0; i < every.size(); ++i) every[i] = i;
    std::vector<std::string> warnings;
    if (Status s = io::check_frames(r, in, every, true, warnings); !s) return fail(s.error().message);
    for (const auto& w : warnings) std::fprintf(stderr, "spt export: warning: %s\n", w.c_str());
    if (web::player_assets().empty())
        return fail("this spt was built without the web player (configure with -DSPT_BUILD_WEB=ON; needs emcc, "
                    "Debian package emscripten)");

    std::string clip;
    {
        std::ifstream f(in, std::ios::binary);
        clip.assign(std::istreambuf_iterator<char>(f), {});
        if (!f && !f.eof()) return fail(in + ": cannot read the file");
    }
    const std::string title = fs::path(in).stem().string();
    if (!folder) {
        if (Status s = import::write_file_atomic(out, self_contained_page(title, clip)); !s) return fail(s.error().message);
        return 0;
    }

    std::error_code ec;
    if (fs::exists(out, ec) && !fs::is_directory(out, ec)) return fail(out + ": exists and is not a folder (--web writes a folder)");
    const bool made_folder = !fs::exists(out, ec);
    fs::create_directories(out, ec);
    if (ec) return fail(out + ": cannot create the folder: " + ec.message());
    std::string clip_name = fs::path(in).filename().string();
    for (const auto& a : web::player_assets())
        if (clip_name == a.name || clip_name == "index.html") clip_name = "clip.spt";  // never over a player file
    // A failure (a full disk) takes back what this run made: the files that were not there
    // before, and the folder if it made it, so that no half site is left to be served.
    std::vector<std::string> made;
    auto put = [&](const std::string& name, const std::string& bytes) -> Status {
        const std::string path = (fs::path(out) / name).string();
        std::error_code e;
        const bool existed = fs::exists(fs::symlink_status(path, e));
        Status s = import::write_file_atomic(path, bytes);
        if (s && !existed) made.push_back(path);
        return s;
    };
    auto undo = [&](const std::string& msg) {
        std::error_code e;
        for (const std::string& p : made) fs::remove(p, e);
        if (made_folder) fs::remove(out, e);  // only if empty: nothing of anyone else's goes
        return fail(msg + (made_folder ? "; " + out + " was removed" : "; the files this run added to " + out + " were removed"));
    };
    for (const auto& a : web::player_assets())
        if (Status s = put(std::string(a.name), std::string(a.bytes)); !s) return undo(s.error().message);
    if (Status s = put(clip_name, clip); !s) return undo(s.error().message);
    if (Status s = put("index.html", hosted_page(title, clip_name)); !s) return undo(s.error().message);
    return 0;
}

}  // namespace spt::cli
