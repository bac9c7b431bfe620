// spt compare (placeholder until implemented)
#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int cmd_compare(int, char**) {
    std::fprintf(stderr, "spt compare: not implemented yet\n");
    return 1;
}

}  // namespace spt::cli
