// Robustness of the whole executable: `tephra --validate` (load, schema,
// Time/DataArchiver, component set-up) on deterministic random mutations of
// the runnable default deck. Every outcome must be exit 0 (still valid),
// 1 (invalid, message names the file) or 3 (valid, feature missing): never a
// crash (signal), a hang (killed by timeout -> 124) or another code.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <fstream>
#include <random>
#include <sstream>

#include "tests/support/TestPaths.h"

namespace {

std::string mutate(std::string s, std::mt19937& rng) {
  auto pick = [&](size_t n) { return n == 0 ? size_t(0) : std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
  switch (pick(6)) {
    case 0: {  // delete a line
      size_t at = pick(s.size());
      size_t b = s.rfind('\n', at), e = s.find('\n', at);
      b = b == std::string::npos ? 0 : b + 1;
      e = e == std::string::npos ? s.size() : e + 1;
      s.erase(b, e - b);
      break;
    }
    case 1: {  // flip a character
      if (!s.empty()) s[pick(s.size())] = "0123456789.-[],<>/aZ_ "[pick(22)];
      break;
    }
    case 2:  // truncate
      s.resize(pick(s.size() + 1));
      break;
    case 3: {  // mangle a number
      size_t at = s.find_first_of("0123456789", pick(s.size()));
      static const char* junk[] = {"nan", "1e999", "-", "0", "-5", "1e30", "[1,2", "", "99999"};
      if (at != std::string::npos) s.replace(at, 1, junk[pick(9)]);
      break;
    }
    case 4: {  // swap a value for an extreme one inside a vector
      size_t at = s.find('[', pick(s.size()));
      if (at != std::string::npos) s.insert(at + 1, pick(2) ? "-" : "1e9");
      break;
    }
    default: {  // rename an element
      size_t at = s.find('<', pick(s.size()));
      if (at != std::string::npos && at + 2 < s.size()) s[at + 1 + pick(2)] = 'Q';
      break;
    }
  }
  return s;
}

int run(const std::string& args, std::string* out) {
  std::string cmd = "timeout 30 " + tephra::test::executable() + " " + args + " 2>&1";
  FILE* p = popen(cmd.c_str(), "r");
  char buf[4096];
  size_t n;
  out->clear();
  while ((n = fread(buf, 1, sizeof buf, p)) > 0) out->append(buf, n);
  int status = pclose(p);
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

}  // namespace

TEST(CommandLineFuzz, MutatedDefaultDeckNeverCrashes) {
  std::ifstream in(tephra::test::source_dir() + "/inputs/mpm/disks.ups");
  std::stringstream s;
  s << in.rdbuf();
  const std::string dir = tephra::test::scratch_dir("cli_fuzz");
  std::mt19937 rng(7u);
  int counts[5] = {0, 0, 0, 0, 0};
  for (int i = 0; i < 150; ++i) {
    std::string m = s.str();
    for (int k = 0, edits = 1 + int(rng() % 3); k < edits; ++k) m = mutate(m, rng);
    const std::string path = dir + "/m" + std::to_string(i) + ".ups";
    std::ofstream(path) << m;
    std::string out;
    int code = run("--validate " + path, &out);
    ASSERT_TRUE(code == 0 || code == 1 || code == 3) << "mutation " << i << " exit " << code << "\n" << out;
    if (code == 1) EXPECT_NE(out.find(path), std::string::npos) << out;
    counts[code]++;
  }
  EXPECT_GT(counts[1], 50);  // most mutations break the deck
}
