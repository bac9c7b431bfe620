// spt export (placeholder until implemented)
#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int cmd_export(int, char**) {
    std::fprintf(stderr, "spt export: not implemented yet\n");
    return 1;
}

}  // namespace spt::cli
