#pragma once
// Minimal logging to stderr; --quiet silences info().
#include <string>

namespace tephra::log {

void set_quiet(bool quiet);
bool quiet();
void info(const std::string& message);     // progress and facts ("read max_Timesteps")
void warning(const std::string& message);  // always printed

}  // namespace tephra::log
