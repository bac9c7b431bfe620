// The spt sub-commands. Each lives in its own cmd_<name>.cpp and gets argv after the command
// name (argv[0] is the command name). They return the process exit code:
// 0 success, 1 failure of the work (bad input file, ...), 2 bad command line.
#pragma once

#include <string>

namespace spt::cli {

// Prints "spt COMMAND: MESSAGE" on stderr and returns 1, the exit status of failed work: the one
// form every command's errors take.
int command_failed(const char* command, const std::string& message);
// A picture beside the painting (`option`: --preview, --side-by-side) failed after `painting`
// was written: said with the message, and that the painting is complete; returns 1.
int extra_output_failed(const char* option, const std::string& painting, const std::string& message);

int cmd_info(int argc, char** argv);
int cmd_verify(int argc, char** argv);
int cmd_render(int argc, char** argv);
int cmd_pack(int argc, char** argv);
int cmd_paint(int argc, char** argv);
int cmd_import(int argc, char** argv);
int cmd_export(int argc, char** argv);
int cmd_compare(int argc, char** argv);
int cmd_cat(int argc, char** argv);
int cmd_plan(int argc, char** argv);
int cmd_farm(int argc, char** argv);

}  // namespace spt::cli
