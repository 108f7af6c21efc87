#pragma once
// Paths the tests need: the source tree, ../shared, the tephra executable and
// a scratch folder under the build tree.
#include <string>

namespace tephra::test {

std::string source_dir();                 // the repository root
std::string shared_dir();                 // ../shared beside the repository
std::string executable();                 // build/bin/tephra
std::string scratch_dir(const std::string& name);  // a fresh, empty folder for one test

// Runs the tephra executable with `args`; returns its exit code and captures
// stdout+stderr into `output`.
int run_tephra(const std::string& args, std::string* output = nullptr);

// The whole file as text (throws when it cannot be opened).
std::string slurp(const std::string& path);
// True when `text` holds a "nan" or "inf" (any case): a .dat file or CSV that
// wrote a non-finite number.
bool has_non_finite(const std::string& text);

}  // namespace tephra::test
