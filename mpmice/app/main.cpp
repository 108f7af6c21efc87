// The tephra executable: see mpmice/app/CommandLine.h for the commands.
#include "mpmice/app/CommandLine.h"

int main(int argc, char** argv) { return tephra::app::run_command_line(argc, argv); }
