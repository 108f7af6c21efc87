// DeckNode value parsing: Vaango's number, vector, boolean and list syntax.
#include <gtest/gtest.h>

#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"

using namespace tephra;

TEST(DeckNode, ParsesVaangoValueSyntax) {
  EXPECT_EQ(*parse_double(" 1.5e3 "), 1500.0);
  EXPECT_FALSE(parse_double("1.5x"));
  EXPECT_FALSE(parse_double(""));
  EXPECT_EQ(*parse_bool("true"), true);
  EXPECT_FALSE(parse_bool("yes"));
  auto v = parse_number_list("[0.0, -1, 2.5e-1]");
  ASSERT_TRUE(v);
  ASSERT_EQ(v->size(), 3u);
  EXPECT_EQ((*v)[2], 0.25);
  EXPECT_FALSE(parse_number_list("[1, 2"));
  EXPECT_FALSE(parse_number_list("[1, a, 2]"));
}

TEST(DeckNode, ErrorsNameFileLineAndElement) {
  auto deck = load_deck_from_string(
      "<Uintah_specification>\n<Time>\n<maxTime>abc</maxTime>\n</Time>\n</Uintah_specification>\n",
      "inline.ups", ".");
  const DeckNode& time = deck->root.require_child("Time");
  try {
    time.get_double("maxTime");
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, "inline.ups");
    EXPECT_EQ(e.where().line, 3);
    EXPECT_EQ(e.where().element, "Time/maxTime");
    EXPECT_EQ(e.code(), ExitCode::InvalidDeck);
  }
}
