#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int command_failed(const char* command, const std::string& message) {
    std::fprintf(stderr, "spt %s: %s\n", command, message.c_str());
    return 1;
}

}  // namespace spt::cli
