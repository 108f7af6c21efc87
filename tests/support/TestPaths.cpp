#include "tests/support/TestPaths.h"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <regex>

#include "core/io/detail/Files.h"

namespace tephra::test {

std::string source_dir() { return TEPHRA_SOURCE_DIR; }
std::string shared_dir() { return TEPHRA_SHARED_DIR; }
std::string executable() { return TEPHRA_EXECUTABLE; }

std::string scratch_dir(const std::string& name) {
  std::filesystem::path p = std::filesystem::path(TEPHRA_TEST_WORK_DIR) / name;
  std::filesystem::remove_all(p);
  std::filesystem::create_directories(p);
  return p.string();
}

int run_tephra(const std::string& args, std::string* output) {
  std::string cmd = executable() + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  if (!pipe) return -1;
  std::array<char, 4096> buf;
  std::string out;
  size_t n;
  while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) out.append(buf.data(), n);
  int status = pclose(pipe);
  if (output) *output = out;
  if (WIFEXITED(status)) return WEXITSTATUS(status);
  return 128 + (WIFSIGNALED(status) ? WTERMSIG(status) : 0);  // a crash
}

std::string slurp(const std::string& path) { return files::read_all(path); }

bool has_non_finite(const std::string& text) {
  static const std::regex bad("(nan|inf)", std::regex::icase);
  return std::regex_search(text, bad);
}

}  // namespace tephra::test
