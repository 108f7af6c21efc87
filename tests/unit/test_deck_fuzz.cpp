// Robustness: deterministic random mutations of real decks (seeded mt19937).
// Loading + validating a mutated deck must either succeed or throw DeckError:
// never crash, hang, or throw anything else. (The property tested: the set of
// outcomes is {ok, DeckError}.)
#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <random>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "core/deck/Validate.h"
#include "tests/support/TestPaths.h"

using namespace tephra;

namespace {

std::string read(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// One random edit of `s`.
std::string mutate(std::string s, std::mt19937& rng) {
  auto pick = [&](size_t n) { return n == 0 ? size_t(0) : std::uniform_int_distribution<size_t>(0, n - 1)(rng); };
  auto line_span = [&](size_t at) {
    size_t b = s.rfind('\n', at);
    b = b == std::string::npos ? 0 : b + 1;
    size_t e = s.find('\n', at);
    return std::make_pair(b, e == std::string::npos ? s.size() : e + 1);
  };
  switch (pick(7)) {
    case 0: {  // delete a line (an element, or half of one)
      auto [b, e] = line_span(pick(s.size()));
      s.erase(b, e - b);
      break;
    }
    case 1: {  // duplicate a line
      auto [b, e] = line_span(pick(s.size()));
      s.insert(e, s.substr(b, e - b));
      break;
    }
    case 2: {  // rename an element: change a letter after a '<'
      size_t at = s.find('<', pick(s.size()));
      if (at != std::string::npos && at + 2 < s.size()) s[at + 1 + pick(2)] = "xyzQ_"[pick(5)];
      break;
    }
    case 3: {  // flip a character
      if (!s.empty()) s[pick(s.size())] = static_cast<char>(pick(256));
      break;
    }
    case 4:  // truncate at a random byte
      s.resize(pick(s.size() + 1));
      break;
    case 5: {  // mangle a number
      size_t at = s.find_first_of("0123456789", pick(s.size()));
      static const char* junk[] = {"nan", "1e999", "-", "1.2.3", "[1,2", "", "-1e-400", "0x1p3", "inf"};
      if (at != std::string::npos) s.replace(at, 1, junk[pick(9)]);
      break;
    }
    default: {  // insert garbage
      static const char* junk[] = {"<", ">", "&", "&#0;", "<!--", "]]>", "<include href=\"\"/>",
                                   "<include href=\"/\"/>", "\"", "<a b=>", "\xff\xfe", "</>"};
      s.insert(pick(s.size() + 1), junk[pick(12)]);
      break;
    }
  }
  return s;
}

}  // namespace

TEST(DeckFuzz, MutatedRealDecksLoadOrFailCleanly) {
  const char* decks[] = {
      "inputs/UintahRelease/MPM/disks_sulsky.ups",
      "inputs/MPM/const_test_hypo.ups",
      "inputs/ICE/riemann_sm.ups",
      "inputs/MPMICE/guni2dRT.ups",
      "inputs/MPM/Impact/cylinderImpact_A_JC.ups",  // uses ../MaterialData includes
      "inputs/ICE/LightTime.ups",                   // CWD-relative include
  };
  std::mt19937 rng(20240601u);
  int ok = 0, rejected = 0;
  auto start = std::chrono::steady_clock::now();
  for (const char* rel : decks) {
    std::string path = test::shared_dir() + "/decks/" + rel;
    std::string text = read(path);
    ASSERT_FALSE(text.empty()) << path;
    std::string dir = path.substr(0, path.rfind('/'));
    for (int i = 0; i < 150; ++i) {
      std::string m = text;
      int edits = 1 + static_cast<int>(rng() % 3);
      for (int k = 0; k < edits; ++k) m = mutate(m, rng);
      try {
        auto deck = load_deck_from_string(m, path, dir);
        validate_deck(*deck);
        ++ok;
      } catch (const DeckError& e) {
        ++rejected;
        EXPECT_FALSE(e.where().file.empty()) << e.what();
      } catch (const std::exception& e) {
        ADD_FAILURE() << rel << " mutation " << i << ": not a DeckError: " << e.what();
      }
    }
  }
  double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(seconds, 20.0);
  // Most mutations break the deck; a few (e.g. a duplicated comment line) do not.
  EXPECT_GT(rejected, 0);
  EXPECT_EQ(ok + rejected, 900);
}
