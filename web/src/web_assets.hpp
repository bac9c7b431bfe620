// The browser player's files (spt-core.js, spt-player.js, spt_core.wasm), compiled into the
// spt tool so that `spt export -o page.html` needs nothing installed beside it.
#pragma once

#include <span>
#include <string_view>

namespace spt::web {

struct Asset {
    std::string_view name;   // file name, e.g. "spt_core.wasm"
    std::string_view bytes;
};

// Empty when spt was built without the web player (SPT_BUILD_WEB=OFF: no emcc).
std::span<const Asset> player_assets();

}  // namespace spt::web
