// Schema validation of decks: one small malformed deck per kind of mistake.
// Each must throw DeckError whose where() names the file, the 1-based line and
// the element path of the (first) problem; messages suggest the nearest valid
// name where one exists. Exact expectations: the line numbers are those of the
// base deck below (line 1 is the XML declaration).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/deck/DeckLoader.h"
#include "core/deck/Schema.h"
#include "core/deck/Validate.h"
#include "tests/support/TestPaths.h"

using namespace tephra;

namespace {

// A minimal deck that validates (checked by MinimalDeckIsValid).
const std::string kBase =
    "<?xml version=\"1.0\"?>\n"                         // 1
    "<Uintah_specification>\n"                          // 2
    "<SimulationComponent type=\"mpm\"/>\n"             // 3
    "<Time>\n"                                          // 4
    "<maxTime>1.0</maxTime>\n"                          // 5
    "<initTime>0.0</initTime>\n"                        // 6
    "<delt_min>1e-9</delt_min>\n"                       // 7
    "<delt_max>1e-3</delt_max>\n"                       // 8
    "<timestep_multiplier>0.5</timestep_multiplier>\n"  // 9
    "</Time>\n"                                         // 10
    "<DataArchiver>\n"                                  // 11
    "<filebase>out.uda</filebase>\n"                    // 12
    "<outputInterval>0.1</outputInterval>\n"            // 13
    "</DataArchiver>\n"                                 // 14
    "<Grid>\n"                                          // 15
    "<Level>\n"                                         // 16
    "<Box label=\"1\">\n"                               // 17
    "<lower>[0,0,0]</lower>\n"                          // 18
    "<upper>[1,1,1]</upper>\n"                          // 19
    "<resolution>[10,10,10]</resolution>\n"             // 20
    "<patches>[1,1,1]</patches>\n"                      // 21
    "</Box>\n"                                          // 22
    "</Level>\n"                                        // 23
    "</Grid>\n"                                         // 24
    "</Uintah_specification>\n";                        // 25

std::string edited(const std::string& from, const std::string& to) {
  size_t at = kBase.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  std::string s = kBase;
  return s.replace(at, from.size(), to);
}

// Loads and validates `xml`; returns the DeckError (fails the test if none).
DeckError expect_error(const std::string& xml, const std::string& name = "bad.ups") {
  try {
    auto deck = load_deck_from_string(xml, name, ".");
    validate_deck(*deck);
  } catch (const DeckError& e) {
    EXPECT_EQ(e.code(), ExitCode::InvalidDeck);
    return e;
  }
  ADD_FAILURE() << "expected a DeckError";
  return DeckError({}, "none");
}

void expect_at(const DeckError& e, int line, const std::string& element) {
  EXPECT_EQ(e.where().file, "bad.ups") << e.what();
  EXPECT_EQ(e.where().line, line) << e.what();
  EXPECT_EQ(e.where().element, element) << e.what();
}

bool says(const DeckError& e, const std::string& text) {
  return std::string(e.what()).find(text) != std::string::npos;
}

void write(const std::string& path, const std::string& text) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream(path) << text;
}

}  // namespace

TEST(DeckValidate, MinimalDeckIsValid) {
  auto deck = load_deck_from_string(kBase, "ok.ups", ".");
  EXPECT_NO_THROW(validate_deck(*deck));
}

TEST(DeckValidate, TruncatedXml) {
  // cut just before "</Grid>": the text ends with "</Level>\n" of line 23;
  // pugixml reports the unclosed <Grid> at the last tag it read, line 23.
  std::string xml = kBase.substr(0, kBase.find("</Grid>"));
  DeckError e = expect_error(xml);
  EXPECT_EQ(e.where().file, "bad.ups");
  EXPECT_EQ(e.where().line, 23);
  EXPECT_TRUE(says(e, "malformed XML")) << e.what();
}

// ../shared/decks/orderAccuracy/MPM/AA.ups is a symbolic link stored as a
// plain file: its whole text is the target path. The error names the file
// and says what it holds.
TEST(DeckValidate, SymlinkStoredAsTextIsNamed) {
  DeckError e = expect_error("../../../StandAlone/inputs/MPM/AA.ups");
  EXPECT_EQ(e.where().file, "bad.ups");
  EXPECT_TRUE(says(e, "malformed XML")) << e.what();
  EXPECT_TRUE(says(e, "'../../../StandAlone/inputs/MPM/AA.ups'")) << e.what();
  EXPECT_TRUE(says(e, "symbolic link")) << e.what();
  // A truncated real deck does not get the remark.
  DeckError t = expect_error(kBase.substr(0, 200));
  EXPECT_FALSE(says(t, "symbolic link")) << t.what();
}

TEST(DeckValidate, EmptyFile) {
  DeckError e = expect_error("");
  EXPECT_EQ(e.where().file, "bad.ups");
  EXPECT_TRUE(says(e, "malformed XML") || says(e, "no root")) << e.what();
}

TEST(DeckValidate, WrongRootElement) {
  std::string xml = edited("<Uintah_specification>", "<Uintah_spec>");
  xml = xml.replace(xml.find("</Uintah_specification>"), 23, "</Uintah_spec>");
  DeckError e = expect_error(xml);
  expect_at(e, 2, "Uintah_spec");
  EXPECT_TRUE(says(e, "Uintah_specification"));
}

TEST(DeckValidate, UnknownElementSuggestsNearest) {
  DeckError e = expect_error(edited("<delt_max>1e-3</delt_max>", "<delt_mx>1e-3</delt_mx>"));
  expect_at(e, 8, "Time/delt_mx");
  EXPECT_TRUE(says(e, "unknown element <delt_mx>"));
  EXPECT_TRUE(says(e, "did you mean 'delt_max'?")) << e.what();
  // the missing delt_max is listed as well
  EXPECT_TRUE(says(e, "missing required element <delt_max>")) << e.what();
}

TEST(DeckValidate, UnknownAttributeSuggestsNearest) {
  DeckError e = expect_error(edited("<Box label=\"1\">", "<Box lable=\"1\">"));
  expect_at(e, 17, "Grid/Level/Box");
  EXPECT_TRUE(says(e, "unknown attribute 'lable'; did you mean 'label'?")) << e.what();
}

TEST(DeckValidate, MissingRequiredElement) {
  DeckError e = expect_error(edited("<delt_min>1e-9</delt_min>\n", ""));
  expect_at(e, 4, "Time");
  EXPECT_TRUE(says(e, "missing required element <delt_min>")) << e.what();
}

TEST(DeckValidate, MissingRequiredAttribute) {
  DeckError e = expect_error(edited("<SimulationComponent type=\"mpm\"/>", "<SimulationComponent/>"));
  expect_at(e, 3, "SimulationComponent");
  EXPECT_TRUE(says(e, "missing required attribute 'type'")) << e.what();
}

TEST(DeckValidate, NotANumber) {
  DeckError e = expect_error(edited("<maxTime>1.0</maxTime>", "<maxTime>1.0x</maxTime>"));
  expect_at(e, 5, "Time/maxTime");
  EXPECT_TRUE(says(e, "expected a number, found '1.0x'")) << e.what();
}

TEST(DeckValidate, NotAnInteger) {
  DeckError e = expect_error(edited("<outputInterval>0.1</outputInterval>",
                                    "<outputTimestepInterval>2.5</outputTimestepInterval>"));
  expect_at(e, 13, "DataArchiver/outputTimestepInterval");
  EXPECT_TRUE(says(e, "expected an integer, found '2.5'")) << e.what();
}

TEST(DeckValidate, BadVector) {
  DeckError e = expect_error(edited("<lower>[0,0,0]</lower>", "<lower>[0,0]</lower>"));
  expect_at(e, 18, "Grid/Level/Box/lower");
  EXPECT_TRUE(says(e, "expected a vector [x, y, z], found '[0,0]'")) << e.what();
}

TEST(DeckValidate, OutOfRangeValue) {
  // maxTime is declared 'positive' (>= 0 in Tephra, see ups_schema.txt)
  DeckError e = expect_error(edited("<maxTime>1.0</maxTime>", "<maxTime>-1</maxTime>"));
  expect_at(e, 5, "Time/maxTime");
  EXPECT_TRUE(says(e, "value -1 out of range: expected >= 0")) << e.what();
}

TEST(DeckValidate, BadEnumValueSuggestsNearest) {
  DeckError e = expect_error(edited("type=\"mpm\"", "type=\"mmp\""));
  expect_at(e, 3, "SimulationComponent");
  EXPECT_TRUE(says(e, "'mmp' is not an allowed value; did you mean 'mpm'?")) << e.what();
}

TEST(DeckValidate, BadBoolean) {
  DeckError e = expect_error(
      edited("<maxTime>1.0</maxTime>",
             "<maxTime>1.0</maxTime><end_on_max_time_exactly>yes</end_on_max_time_exactly>"));
  expect_at(e, 5, "Time/end_on_max_time_exactly");
  EXPECT_TRUE(says(e, "expected true or false, found 'yes'")) << e.what();
}

TEST(DeckValidate, DuplicateSingleElement) {
  DeckError e = expect_error(edited("<initTime>0.0</initTime>", "<maxTime>2</maxTime>"));
  expect_at(e, 6, "Time/maxTime");
  EXPECT_TRUE(says(e, "given more than once (first at bad.ups:5)")) << e.what();
}

TEST(DeckValidate, OneOfGroup) {
  // DataArchiver: ONE_OF(outputInterval, outputTimestepInterval)
  DeckError e = expect_error(edited("<outputInterval>0.1</outputInterval>\n", ""));
  expect_at(e, 11, "DataArchiver");
  EXPECT_TRUE(says(e, "needs exactly one child element of outputInterval, outputTimestepInterval, found 0"))
      << e.what();
  DeckError two = expect_error(edited(
      "<outputInterval>0.1</outputInterval>",
      "<outputInterval>0.1</outputInterval><outputTimestepInterval>2</outputTimestepInterval>"));
  EXPECT_TRUE(says(two, "found 2")) << two.what();
}

TEST(DeckValidate, TextInNoDataElement) {
  DeckError e = expect_error(edited("<Level>", "<Level>oops"));
  expect_at(e, 16, "Grid/Level");
  EXPECT_TRUE(says(e, "expected no text, found 'oops'")) << e.what();
}

TEST(DeckValidate, LegacySpellingsAreAliases) {
  // Uintah's max_Timesteps and the older end_at_max_time_exactly are accepted ...
  auto ok = load_deck_from_string(
      edited("<maxTime>1.0</maxTime>",
             "<maxTime>1.0</maxTime><max_Timesteps>10</max_Timesteps>"
             "<end_at_max_time_exactly>true</end_at_max_time_exactly>"),
      "ok.ups", ".");
  EXPECT_NO_THROW(validate_deck(*ok));
  // ... with the type of the name they stand for ...
  DeckError t = expect_error(
      edited("<maxTime>1.0</maxTime>", "<maxTime>1.0</maxTime><max_Timesteps>x</max_Timesteps>"));
  expect_at(t, 5, "Time/max_Timesteps");
  // ... and both spellings at once is ambiguous.
  DeckError e = expect_error(edited(
      "<maxTime>1.0</maxTime>",
      "<maxTime>1.0</maxTime><max_Timesteps>10</max_Timesteps><max_timesteps>5</max_timesteps>"));
  EXPECT_TRUE(says(e, "<max_timesteps> given more than once (first at bad.ups:5 as <max_Timesteps>)"))
      << e.what();
}

TEST(DeckValidate, MissingIncludeFile) {
  std::string dir = test::scratch_dir("deck_validate_missing_include");
  write(dir + "/deck.ups", edited("<Grid>", "<include href=\"nothere.xml\"/>\n<Grid>"));
  try {
    load_deck(dir + "/deck.ups");
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, dir + "/deck.ups");
    EXPECT_EQ(e.where().line, 15);
    EXPECT_EQ(e.where().element, "include");
    EXPECT_TRUE(says(e, "'nothere.xml' not found")) << e.what();
  }
}

TEST(DeckValidate, IncludeCycle) {
  std::string dir = test::scratch_dir("deck_validate_include_cycle");
  write(dir + "/deck.ups", edited("<Grid>", "<include href=\"a.xml\"/>\n<Grid>"));
  write(dir + "/a.xml", "<Uintah_Include>\n<include href=\"b.xml\"/>\n</Uintah_Include>\n");
  write(dir + "/b.xml", "<Uintah_Include>\n\n<include href=\"a.xml\"/>\n</Uintah_Include>\n");
  try {
    load_deck(dir + "/deck.ups");
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_EQ(std::filesystem::path(e.where().file).filename(), "b.xml");
    EXPECT_EQ(e.where().line, 3);
    EXPECT_EQ(e.where().element, "include");
    EXPECT_TRUE(says(e, "include cycle")) << e.what();
  }
}

TEST(DeckValidate, ErrorInIncludedFileNamesThatFile) {
  std::string dir = test::scratch_dir("deck_validate_error_in_include");
  write(dir + "/deck.ups", edited("<Grid>", "<include href=\"phys.xml\"/>\n<Grid>"));
  write(dir + "/phys.xml",
        "<Uintah_Include>\n<PhysicalConstants>\n<gravity>[0,0]</gravity>\n"
        "</PhysicalConstants>\n</Uintah_Include>\n");
  auto deck = load_deck(dir + "/deck.ups");
  try {
    validate_deck(*deck);
    FAIL() << "expected a DeckError";
  } catch (const DeckError& e) {
    EXPECT_EQ(e.where().file, dir + "/phys.xml");
    EXPECT_EQ(e.where().line, 3);
    EXPECT_EQ(e.where().element, "PhysicalConstants/gravity");
  }
}

// Include rule (DeckLoader.h): next to the including file first, then
// relative to each parent folder in turn.
TEST(DeckInclude, NextToTheFileFirstThenParentFolders) {
  std::string root = test::scratch_dir("deck_include_rule");
  auto gravity = [](const char* g) {
    return std::string("<Uintah_Include>\n<PhysicalConstants>\n<gravity>") + g +
           "</gravity>\n</PhysicalConstants>\n</Uintah_Include>\n";
  };
  // same name next to the deck and in its parent: the one next to it wins
  write(root + "/inputs/MPM/g.xml", gravity("[1,0,0]"));
  write(root + "/inputs/g.xml", gravity("[2,0,0]"));
  // only in a parent folder ("../MaterialData/x.xml" idiom and plain name)
  write(root + "/inputs/only_up.xml",
        "<Uintah_Include>\n<Meta>\n<title>up</title>\n</Meta>\n</Uintah_Include>\n");
  // CWD-style path relative to an ancestor: inputs/ICE/EOSData/e.xml
  write(root + "/inputs/ICE/EOSData/e.xml",
        "<Uintah_Include>\n<include href=\"f.xml\"/>\n</Uintah_Include>\n");
  // an included file resolves its own includes from its own folder
  write(root + "/inputs/ICE/EOSData/f.xml",
        "<Uintah_Include>\n<MPMICE>\n<vol_frac_convergence_tolerance>1e-9"
        "</vol_frac_convergence_tolerance>\n</MPMICE>\n</Uintah_Include>\n");
  write(root + "/inputs/MPM/deck.ups",
        edited("<Grid>", "<include href=\"g.xml\"/>\n<include href=\"only_up.xml\"/>\n"
                         "<include href=\"inputs/ICE/EOSData/e.xml\"/>\n<Grid>"));
  auto deck = load_deck(root + "/inputs/MPM/deck.ups");
  EXPECT_NO_THROW(validate_deck(*deck));
  auto pcs = deck->root.children_named("PhysicalConstants");
  ASSERT_EQ(pcs.size(), 1u);
  EXPECT_EQ(pcs[0]->get_vec3("gravity"), Vec3(1, 0, 0));
  EXPECT_EQ(pcs[0]->file, root + "/inputs/MPM/g.xml");
  ASSERT_TRUE(deck->root.has_child("Meta"));
  EXPECT_EQ(deck->root.child("Meta")->get_string("title"), "up");
  ASSERT_TRUE(deck->root.has_child("MPMICE"));
  EXPECT_EQ(deck->root.child("MPMICE")->get_double("vol_frac_convergence_tolerance"), 1e-9);
  EXPECT_EQ(deck->files.size(), 5u);
}

// Schema features on a small hand-written schema (closed-form expectations).
namespace {
const char* kToySchema =
    "Uintah_specification REQUIRED NO_DATA\n"
    "$piece OPTIONAL NO_DATA attr=label:OPTIONAL:STRING label_ref=label\n"
    "$piece/radius REQUIRED DOUBLE range=0..10\n"
    "Uintah_specification/piece MULTIPLE REF:piece\n"
    "Uintah_specification/model MULTIPLE NO_DATA attr=type:REQUIRED:STRING:jc|linear "
    "all_or_none=CHILD:p|q\n"
    "Uintah_specification/model/A REQUIRED DOUBLE applies=type:jc\n"
    "Uintah_specification/model/K REQUIRED DOUBLE applies=type:linear\n"
    "Uintah_specification/model/p OPTIONAL MULTIPLE_INTEGERS\n"
    "Uintah_specification/model/q OPTIONAL MULTIPLE_VECTORS range=positive\n";

std::vector<DeckProblem> toy(const std::string& body) {
  static auto schema = Schema::parse(kToySchema, "toy");
  auto deck = load_deck_from_string(
      "<Uintah_specification>\n" + body + "</Uintah_specification>\n", "toy.ups", ".");
  return check_deck(deck->root, *schema);
}
}  // namespace

TEST(DeckSchema, NeedAppliesToFollowsTheParentType) {
  EXPECT_TRUE(toy("<model type=\"jc\"><A>1</A></model>\n").empty());
  auto missing = toy("<model type=\"linear\"><A>1</A></model>\n");
  ASSERT_EQ(missing.size(), 2u);
  EXPECT_NE(missing[0].message.find("<A> is only allowed when <model> has type = one of jc"),
            std::string::npos) << missing[0].message;
  EXPECT_EQ(missing[1].message, "missing required element <K> (required when type = 'linear')");
}

TEST(DeckSchema, AllOrNoneAndLists) {
  EXPECT_TRUE(toy("<model type=\"jc\"><A>1</A><p>[1, 2, 3, 4]</p>"
                  "<q>[[1,2,3],[4,5,6]]</q></model>\n").empty());
  auto half = toy("<model type=\"jc\"><A>1</A><p>[1]</p></model>\n");
  ASSERT_EQ(half.size(), 1u);
  EXPECT_EQ(half[0].message, "needs all or none of the child elements p, q");
  auto bad = toy("<model type=\"jc\"><A>1</A><p>[1.5]</p><q>[[1,2,3],[4,-5,6]]</q></model>\n");
  ASSERT_EQ(bad.size(), 2u);
  EXPECT_EQ(bad[0].message, "expected a list of integers, found '[1.5]'");
  EXPECT_EQ(bad[1].message, "value -5 out of range: expected >= 0");
}

TEST(DeckSchema, CommonTagsAndLabelReferences) {
  EXPECT_TRUE(toy("<piece label=\"a\"><radius>2</radius></piece>\n<piece label=\"a\"/>\n").empty());
  auto range = toy("<piece><radius>11</radius></piece>\n");
  ASSERT_EQ(range.size(), 1u);
  EXPECT_EQ(range[0].message, "value 11 out of range: expected in [0, 10]");
  auto undefined = toy("<piece label=\"b\"><radius>2</radius></piece>\n<piece label=\"c\"/>\n");
  ASSERT_EQ(undefined.size(), 1u);
  EXPECT_EQ(undefined[0].where.line, 3);
  EXPECT_NE(undefined[0].message.find("refers to a piece not defined before it; did you mean 'b'?"),
            std::string::npos) << undefined[0].message;
  auto twice = toy("<piece label=\"b\"><radius>2</radius></piece>\n"
                   "<piece label=\"b\"><radius>3</radius></piece>\n");
  ASSERT_EQ(twice.size(), 1u);
  EXPECT_EQ(twice[0].message, "label 'b' of <piece> already defined at toy.ups:2");
}

TEST(DeckSchema, EditDistance) {
  // Levenshtein: kitten -> sitting = 3 (two substitutions, one insertion)
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  // an adjacent transposition counts 1 (optimal string alignment distance)
  EXPECT_EQ(edit_distance("mmp", "mpm"), 1u);
  EXPECT_EQ(edit_distance("mmp", "impm"), 2u);
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(nearest_name("maxTme", {"maxTime", "initTime", "delt_max"}), "maxTime");
}

TEST(DeckSchema, BuiltinSchemaParses) {
  const Schema& s = Schema::builtin();
  EXPECT_EQ(s.root().name, "Uintah_specification");
  ASSERT_NE(s.common("geom_object"), nullptr);
  EXPECT_EQ(s.root().children.count("Time"), 1u);
}

TEST(DeckValidate, Latin1DeclaredDeckLoads) {
  // Vaango's files declare encoding='ISO-8859-1'; a byte such as 0xE9 ('é' in
  // Latin-1) is then a valid character, not broken UTF-8.
  std::string xml = edited("<?xml version=\"1.0\"?>",
                           "<?xml version='1.0' encoding='ISO-8859-1'?>\n<!-- caf\xe9 -->");
  xml = xml.replace(xml.find("<Grid>"), 6, "<Meta><title>caf\xe9</title></Meta>\n<Grid>");
  auto deck = load_deck_from_string(xml, "latin1.ups", ".");
  EXPECT_NO_THROW(validate_deck(*deck));
  // converted to UTF-8 inside Tephra: 0xE9 -> C3 A9
  EXPECT_EQ(deck->root.child("Meta")->get_string("title"), "caf\xc3\xa9");
  // <Meta> sits where <Grid> was (line 15), one line down for the comment
  EXPECT_EQ(deck->root.child("Meta")->line, 16);
}
