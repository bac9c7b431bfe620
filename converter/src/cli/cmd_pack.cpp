// spt pack (placeholder until implemented)
#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int cmd_pack(int, char**) {
    std::fprintf(stderr, "spt pack: not implemented yet\n");
    return 1;
}

}  // namespace spt::cli
