#include "core/base/Log.h"

#include <iostream>

namespace tephra::log {

namespace {
bool g_quiet = false;
}

void set_quiet(bool q) { g_quiet = q; }
bool quiet() { return g_quiet; }
void info(const std::string& m) {
  if (!g_quiet) std::cerr << "tephra: " << m << "\n";
}
void warning(const std::string& m) { std::cerr << "tephra: warning: " << m << "\n"; }

}  // namespace tephra::log
