// Every real Vaango deck under ../shared/decks loads and passes schema
// validation (one test per deck), so Tephra accepts the decks users have.
// The one exception, orderAccuracy/MPM/AA.ups, is not XML: in Vaango's git
// tree it is a symbolic link, and the copy stores the link target (a path) as
// the file's text. It must be rejected as a DeckError (exit 1).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "core/deck/DeckLoader.h"
#include "core/deck/Validate.h"
#include "tests/support/TestPaths.h"

using namespace tephra;
namespace fs = std::filesystem;

namespace {

const char* kSymlinkDeck = "orderAccuracy/MPM/AA.ups";

std::vector<std::string> real_decks() {
  std::vector<std::string> out;
  fs::path root = fs::path(test::shared_dir()) / "decks";
  if (!fs::is_directory(root)) return out;
  for (const auto& e : fs::recursive_directory_iterator(root))
    if (e.is_regular_file() && e.path().extension() == ".ups") {
      std::string rel = fs::relative(e.path(), root).string();
      if (rel != kSymlinkDeck) out.push_back(rel);
    }
  std::sort(out.begin(), out.end());
  return out;
}

std::string test_name(const testing::TestParamInfo<std::string>& info) {
  std::string s = info.param;
  for (char& c : s)
    if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
  return s;
}

class RealDeck : public testing::TestWithParam<std::string> {};

}  // namespace

TEST_P(RealDeck, LoadsAndValidates) {
  std::string path = test::shared_dir() + "/decks/" + GetParam();
  try {
    auto deck = load_deck(path);
    validate_deck(*deck);
  } catch (const DeckError& e) {
    FAIL() << e.what();
  }
}

INSTANTIATE_TEST_SUITE_P(SharedDecks, RealDeck, testing::ValuesIn(real_decks()), test_name);

TEST(RealDeckSet, HasTheDecksOfTheReadme) {
  // decks/README.md lists 23 .ups files (22 XML + the symlink copy).
  EXPECT_EQ(real_decks().size(), 22u);
}

TEST(RealDeckSet, SymlinkCopyIsADeckError) {
  std::string path = test::shared_dir() + "/decks/" + kSymlinkDeck;
  ASSERT_TRUE(fs::is_regular_file(path));
  try {
    auto deck = load_deck(path);
    validate_deck(*deck);
    FAIL() << "a text file holding a path is not a deck";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, path);
    EXPECT_EQ(e.code(), ExitCode::InvalidDeck);
  }
}
