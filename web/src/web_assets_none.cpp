// spt built without the web player (SPT_BUILD_WEB=OFF): no assets to export.
#include "web_assets.hpp"

namespace spt::web {

std::span<const Asset> player_assets() { return {}; }

}  // namespace spt::web
