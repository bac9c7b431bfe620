// spt paint (placeholder until implemented)
#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int cmd_paint(int, char**) {
    std::fprintf(stderr, "spt paint: not implemented yet\n");
    return 1;
}

}  // namespace spt::cli
