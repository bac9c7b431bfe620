// spt verify (placeholder until implemented)
#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int cmd_verify(int, char**) {
    std::fprintf(stderr, "spt verify: not implemented yet\n");
    return 1;
}

}  // namespace spt::cli
