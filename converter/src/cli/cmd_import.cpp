// spt import (placeholder until implemented)
#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int cmd_import(int, char**) {
    std::fprintf(stderr, "spt import: not implemented yet\n");
    return 1;
}

}  // namespace spt::cli
