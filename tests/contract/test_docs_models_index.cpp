// docs/models/README.md, the index of the solid models, cannot go stale:
//  - every registered constitutive model key (constitutive_model_types(), what
//    `tephra --list constitutive_model` prints) has a row "| `key` | ... |";
//  - every page the row links ("(page.md)") exists in docs/models/ and names the key;
//  - every test named in the row (test_<name>) is a file tests/{unit,contract,verification}/test_<name>.cpp;
//  - every row's key is registered (no row for a model that was removed).
#include <gtest/gtest.h>

#include <filesystem>
#include <regex>
#include <set>
#include <sstream>
#include <string>

#include "models/solid/ConstitutiveModel.h"
#include "tests/support/TestPaths.h"

namespace tephra {
namespace {

namespace fs = std::filesystem;

TEST(DocsModelsIndex, EveryRegisteredModelHasARowWithExistingPagesAndTests) {
  const fs::path docs = fs::path(test::source_dir()) / "docs" / "models";
  const std::string index = test::slurp((docs / "README.md").string());
  std::set<std::string> rows;
  std::istringstream in(index);
  std::string line;
  const std::regex row_key("^\\| `([^`]+)` \\|");
  const std::regex link("\\(([A-Za-z0-9_.-]+\\.md)\\)");
  const std::regex test_name("\\b(test_[a-z0-9_]+)\\b");
  const std::vector<std::string> registered = constitutive_model_types();
  const std::set<std::string> keys(registered.begin(), registered.end());
  while (std::getline(in, line)) {
    std::smatch m;
    if (!std::regex_search(line, m, row_key)) continue;
    const std::string key = m[1];
    rows.insert(key);
    EXPECT_TRUE(keys.count(key)) << "docs/models/README.md has a row for '" << key << "', which is not registered";
    int pages = 0;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), link); it != std::sregex_iterator(); ++it) {
      const fs::path page = docs / (*it)[1].str();
      ++pages;
      ASSERT_TRUE(fs::exists(page)) << "row '" << key << "' links " << page << ", which does not exist";
      EXPECT_NE(test::slurp(page.string()).find(key), std::string::npos)
          << page << " (linked from the row of '" << key << "') does not name the key";
    }
    EXPECT_GE(pages, 1) << "row '" << key << "' links no page";
    int tests = 0;
    for (auto it = std::sregex_iterator(line.begin(), line.end(), test_name); it != std::sregex_iterator(); ++it) {
      const std::string name = (*it)[1].str() + ".cpp";
      bool found = false;
      for (const char* tier : {"unit", "contract", "verification"})
        found = found || fs::exists(fs::path(test::source_dir()) / "tests" / tier / name);
      ++tests;
      EXPECT_TRUE(found) << "row '" << key << "' names " << name << ", which is in no test folder";
    }
    EXPECT_GE(tests, 1) << "row '" << key << "' names no test";
  }
  for (const std::string& k : registered)
    EXPECT_TRUE(rows.count(k)) << "registered model '" << k << "' has no row in docs/models/README.md";
}

}  // namespace
}  // namespace tephra
