#pragma once
// tephra DECK [--output DIR] [--max-steps N] [--end-time T] [--threads N] [--quiet]
// tephra --validate DECK
// tephra --restart DIR [--checkpoint N]
// tephra --list FAMILY
// tephra extract DIR --var LABEL [--material M] [--step N|last | --time T | --all-times]
// Returns the process exit code (core/base/Errors.h).
namespace tephra::app {

int run_command_line(int argc, char** argv);

}  // namespace tephra::app
