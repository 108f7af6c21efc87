// make_grid on inline decks: both ways of giving the cell count, the patch
// split, validation errors located at the element, and every shared deck.
#include <gtest/gtest.h>

#include <filesystem>
#include <iostream>
#include <string>

#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "core/grid/BoundaryConditions.h"
#include "core/grid/Grid.h"
#include "tests/support/TestPaths.h"

using namespace tephra;

namespace {

// Wraps a <Grid> body into a deck; the <Grid> element starts on line 2.
std::unique_ptr<Deck> grid_deck(const std::string& grid_body) {
  return load_deck_from_string("<Uintah_specification>\n<Grid>\n" + grid_body + "</Grid>\n</Uintah_specification>\n",
                               "inline.ups", ".");
}

Grid grid_from(const std::string& body) {
  auto deck = grid_deck(body);
  return make_grid(deck->root.require_child("Grid"));
}

// Expects a DeckError at `line` whose element path ends with `element`.
void expect_deck_error(const std::string& body, int line, const std::string& element) {
  auto deck = grid_deck(body);
  try {
    make_grid(deck->root.require_child("Grid"));
    FAIL() << "expected a DeckError for\n" << body;
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, "inline.ups");
    EXPECT_EQ(e.where().line, line) << e.what();
    const std::string& el = e.where().element;
    EXPECT_EQ(el.substr(el.size() - std::min(el.size(), element.size())), element) << e.what();
  }
}

void expect_missing_feature(const std::string& body) {
  auto deck = grid_deck(body);
  EXPECT_THROW(make_grid(deck->root.require_child("Grid")), MissingFeature) << body;
}

}  // namespace

TEST(GridMake, ResolutionForm) {
  Grid g = grid_from(
      "<Level><Box><lower>[0,0,0]</lower><upper>[1,2,0.5]</upper><resolution>[10,20,1]</resolution>"
      "<extraCells>[1,1,0]</extraCells><patches>[2,1,1]</patches></Box></Level>\n");
  EXPECT_EQ(g.cells, IntVec3(10, 20, 1));
  // dx = (upper - lower) / resolution
  EXPECT_DOUBLE_EQ(g.dx[0], 0.1);
  EXPECT_DOUBLE_EQ(g.dx[1], 0.1);
  EXPECT_DOUBLE_EQ(g.dx[2], 0.5);
  EXPECT_EQ(g.extra_cells, IntVec3(1, 1, 0));
  EXPECT_EQ(g.periodic, IntVec3::Zero());
  ASSERT_EQ(g.patches.size(), 2u);
  EXPECT_EQ(g.patches[0].lo, IntVec3(0, 0, 0));
  EXPECT_EQ(g.patches[0].hi, IntVec3(5, 20, 1));
  EXPECT_EQ(g.patches[1].lo, IntVec3(5, 0, 0));
  // Extra cells belong to the patch on that domain face only.
  EXPECT_EQ(g.patches[0].extra_lo, IntVec3(-1, -1, 0));
  EXPECT_EQ(g.patches[0].extra_hi, IntVec3(5, 21, 1));
  EXPECT_EQ(g.patches[1].extra_lo, IntVec3(5, -1, 0));
  EXPECT_EQ(g.patches[1].extra_hi, IntVec3(11, 21, 1));
}

TEST(GridMake, SpacingFormAndDefaults) {
  // massX.ups: [0,5]^3 with spacing 0.5 -> 10 cells per direction.
  Grid g = grid_from(
      "<Level><Box><lower>[0,0,0]</lower><upper>[5,5,5]</upper></Box>"
      "<spacing>[0.5,0.5,0.5]</spacing><periodic>[1,0,1]</periodic></Level>\n");
  EXPECT_EQ(g.cells, IntVec3(10, 10, 10));
  EXPECT_DOUBLE_EQ(g.dx[1], 0.5);
  EXPECT_EQ(g.extra_cells, IntVec3::Zero());  // extraCells default [0,0,0]
  EXPECT_EQ(g.periodic, IntVec3(1, 0, 1));
  ASSERT_EQ(g.patches.size(), 1u);  // patches default [1,1,1]
  // A spacing that divides the box only up to round-off: 1.2/0.001 = 1199.9999999999998.
  Grid a6 = grid_from(
      "<Level><Box><lower>[-0.6,-0.0005,-0.0005]</lower><upper>[0.6,0.0005,0.0005]</upper></Box>"
      "<spacing>[0.001,0.001,0.001]</spacing></Level>\n");
  EXPECT_EQ(a6.cells, IntVec3(1200, 1, 1));
}

TEST(GridMake, PatchSplitIsEvenAndSumsToTotal) {
  // 10 cells in 4 patches: 3,3,2,2 (the first n % p patches get one more cell).
  const std::vector<int> b = split_evenly(10, 4);
  EXPECT_EQ(b, (std::vector<int>{0, 3, 6, 8, 10}));
  for (int n = 1; n <= 40; ++n)
    for (int p = 1; p <= n; ++p) {
      const std::vector<int> s = split_evenly(n, p);
      ASSERT_EQ(s.front(), 0);
      ASSERT_EQ(s.back(), n);
      for (int q = 0; q < p; ++q) {
        const int len = s[q + 1] - s[q];
        ASSERT_TRUE(len == n / p || len == n / p + 1);
        ASSERT_EQ(len, n / p + (q < n % p ? 1 : 0));
      }
    }
  Grid g = grid_from(
      "<Level><Box><lower>[0,0,0]</lower><upper>[1,1,1]</upper><resolution>[51,51,7]</resolution>"
      "<patches>[2,3,4]</patches></Box></Level>\n");
  ASSERT_EQ(g.patches.size(), 24u);
  long long total = 0;
  for (size_t n = 0; n < g.patches.size(); ++n) {
    const Patch& p = g.patches[n];
    EXPECT_EQ(p.id, int(n));
    total += p.cells().size();
  }
  EXPECT_EQ(total, g.num_interior_cells());  // 51*51*7, each cell exactly once:
  for (int k = 0; k < 7; ++k)
    for (int j = 0; j < 51; ++j)
      for (int i = 0; i < 51; ++i) {
        const int owner = g.patch_owning_cell(IntVec3(i, j, k));
        ASSERT_GE(owner, 0);
        ASSERT_TRUE(g.patches[owner].cells().contains(i, j, k));
      }
  EXPECT_EQ(g.patch_owning_cell(IntVec3(-1, 0, 0)), -1);
}

TEST(GridMake, MultiBoxTilingMergesAndOthersAreMissing) {
  Grid g = grid_from(
      "<Level>"
      "<Box><lower>[0,0,0]</lower><upper>[1,1,1]</upper><resolution>[4,4,4]</resolution><patches>[2,1,1]</patches></Box>"
      "<Box><lower>[1,0,0]</lower><upper>[1.5,1,1]</upper><resolution>[2,4,4]</resolution></Box>"
      "</Level>\n");
  EXPECT_EQ(g.cells, IntVec3(6, 4, 4));
  ASSERT_EQ(g.patches.size(), 3u);
  EXPECT_EQ(g.patches[2].lo, IntVec3(4, 0, 0));
  EXPECT_EQ(g.patches[2].hi, IntVec3(6, 4, 4));
  // L-shaped union (gap in the bounding box).
  expect_missing_feature(
      "<Level>"
      "<Box><lower>[0,0,0]</lower><upper>[1,1,1]</upper><resolution>[4,4,4]</resolution></Box>"
      "<Box><lower>[1,1,0]</lower><upper>[2,2,1]</upper><resolution>[4,4,4]</resolution></Box>"
      "</Level>\n");
  // Different spacing.
  expect_missing_feature(
      "<Level>"
      "<Box><lower>[0,0,0]</lower><upper>[1,1,1]</upper><resolution>[4,4,4]</resolution></Box>"
      "<Box><lower>[1,0,0]</lower><upper>[2,1,1]</upper><resolution>[8,4,4]</resolution></Box>"
      "</Level>\n");
  // Overlap.
  expect_missing_feature(
      "<Level>"
      "<Box><lower>[0,0,0]</lower><upper>[1,1,1]</upper><resolution>[4,4,4]</resolution></Box>"
      "<Box><lower>[0.5,0,0]</lower><upper>[1.5,1,1]</upper><resolution>[4,4,4]</resolution></Box>"
      "</Level>\n");
}

TEST(GridMake, UnsupportedFormsAreMissingFeatures) {
  const std::string box = "<Box><lower>[0,0,0]</lower><upper>[1,1,1]</upper><resolution>[4,4,4]</resolution></Box>";
  expect_missing_feature("<Level>" + box + "</Level><Level>" + box + "</Level>\n");
  expect_missing_feature(
      "<Level><Box><lower>[0,0,0]</lower><upper>[1,1,1]</upper><resolution>[4,4,4]</resolution>"
      "<autoPatch>2</autoPatch></Box></Level>\n");
}

TEST(GridMake, ErrorsAreLocatedAtTheElement) {
  // Line numbers: the body starts on line 3 (line 1 root, line 2 <Grid>).
  expect_deck_error("<Level>\n<Box>\n<lower>[0,0,0]</lower>\n<upper>[1,0,1]</upper>\n"
                    "<resolution>[4,4,4]</resolution>\n</Box>\n</Level>\n",
                    6, "Box/upper");
  expect_deck_error("<Level>\n<Box>\n<lower>[0,0,0]</lower>\n<upper>[1,1,1]</upper>\n"
                    "<resolution>[4,0,4]</resolution>\n</Box>\n</Level>\n",
                    7, "Box/resolution");
  expect_deck_error("<Level>\n<Box>\n<lower>[0,0,0]</lower>\n<upper>[1,1,1]</upper>\n"
                    "<resolution>[4,4,4]</resolution>\n<extraCells>[1,-1,1]</extraCells>\n</Box>\n</Level>\n",
                    8, "Box/extraCells");
  expect_deck_error("<Level>\n<Box>\n<lower>[0,0,0]</lower>\n<upper>[1,1,1]</upper>\n"
                    "<resolution>[4,4,4]</resolution>\n<patches>[5,1,1]</patches>\n</Box>\n</Level>\n",
                    8, "Box/patches");
  // 1/0.3 = 3.33 cells: not a whole number.
  expect_deck_error("<Level>\n<Box>\n<lower>[0,0,0]</lower>\n<upper>[1,1,1]</upper>\n</Box>\n"
                    "<spacing>[0.3,0.5,0.5]</spacing>\n</Level>\n",
                    8, "Level/spacing");
  // Neither resolution nor spacing.
  expect_deck_error("<Level>\n<Box>\n<lower>[0,0,0]</lower>\n<upper>[1,1,1]</upper>\n</Box>\n</Level>\n", 4,
                    "Level/Box");
  // Both resolution and spacing.
  expect_deck_error("<Level>\n<Box>\n<lower>[0,0,0]</lower>\n<upper>[1,1,1]</upper>\n"
                    "<resolution>[4,4,4]</resolution>\n</Box>\n<spacing>[0.25,0.25,0.25]</spacing>\n</Level>\n",
                    7, "Box/resolution");
  expect_deck_error("<Level>\n<Box>\n<lower>[0,0,0]</lower>\n<upper>[1,1,1]</upper>\n"
                    "<resolution>[4,4,4]</resolution>\n</Box>\n<periodic>[2,0,0]</periodic>\n</Level>\n",
                    9, "Level/periodic");
  expect_deck_error("<Level>\n</Level>\n", 3, "Grid/Level");
  expect_deck_error("\n", 2, "Grid");
}

// Every shared deck with a <Grid>: the grid and its boundary conditions parse,
// or the deck asks for a feature we do not have (MissingFeature).
TEST(GridMake, EverySharedDeckParsesOrIsMissingFeature) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(test::shared_dir()) / "decks";
  int with_grid = 0, parsed = 0;
  for (const auto& entry : fs::recursive_directory_iterator(root)) {
    if (entry.path().extension() != ".ups") continue;
    std::unique_ptr<Deck> deck;
    try {
      deck = load_deck(entry.path().string());
    } catch (const TephraError& e) {
      std::cerr << "skipped, does not load: " << e.what() << "\n";  // the loader's business
      continue;
    }
    const DeckNode* grid = deck->root.child("Grid");
    if (!grid) continue;
    ++with_grid;
    try {
      Grid g = make_grid(*grid);
      BoundaryConditions bcs = parse_boundary_conditions(*grid);
      EXPECT_GE(g.num_interior_cells(), 1);
      ++parsed;
    } catch (const MissingFeature&) {
    } catch (const TephraError& e) {
      ADD_FAILURE() << entry.path() << ": " << e.what();
    }
  }
  EXPECT_GE(with_grid, 20);
  EXPECT_EQ(parsed, with_grid);  // none of the shared decks needs a missing grid feature
}
