#include <cstdio>

#include "cli/commands.hpp"

namespace spt::cli {

int command_failed(const char* command, const std::string& message) {
    std::fprintf(stderr, "spt %s: %s\n", command, message.c_str());
    return 1;
}

int extra_output_failed(const char* option, const std::string& painting, const std::string& message) {
    // Exit 1 still: a script asked for both files and has one; the message says which.
    std::fprintf(stderr, "spt paint: %s %s; %s is complete and valid, only the %s was not written\n", option,
                 message.c_str(), painting.c_str(), option + 2);
    return 1;
}

}  // namespace spt::cli
