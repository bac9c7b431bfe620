// spt render (placeholder until implemented)
#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int cmd_render(int, char**) {
    std::fprintf(stderr, "spt render: not implemented yet\n");
    return 1;
}

}  // namespace spt::cli
