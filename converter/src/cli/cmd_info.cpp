// spt info (placeholder until implemented)
#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int cmd_info(int, char**) {
    std::fprintf(stderr, "spt info: not implemented yet\n");
    return 1;
}

}  // namespace spt::cli
