// spt export to the web: the browser player (web/) with a clip, as one self-contained page or
// as a folder to host.
#pragma once

#include <string>

namespace spt::cli {

// True when `spt export` should write for the web: `--web` given, or OUT ending in .html.
bool is_web_export(const std::string& out, bool web_flag);

// `folder` false: OUT.html, one page holding the player, the WebAssembly module and the clip
// (plays offline, from a double-click). `folder` true: OUT/ receives spt-player.js,
// spt-core.js, spt_core.wasm, the clip and an index.html, for a web server. Every frame of IN
// is decoded first, so a damaged clip is refused rather than exported. Returns the exit code.
int export_web(const std::string& in, const std::string& out, bool folder);

}  // namespace spt::cli
