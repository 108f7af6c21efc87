// tephra.xdmf parsed back: structure per the XDMF model (Temporal collection
// of Spatial collections; 3DCoRectMesh with ORIGIN_DXDYDZ listed z y x and
// Dimensions = nodes per direction, slowest first; Polyvertex particle sets),
// and every HDF5 reference resolves to a dataset of the declared dimensions.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <filesystem>
#include <pugixml.hpp>
#include <sstream>

#include "core/io/OutputWriter.h"
#include "tests/support/TestPaths.h"
#include "tests/support/XdmfCheck.h"
#include "tests/unit/test_io_sample.h"

using namespace tephra;

namespace {

std::vector<double> numbers(const std::string& text) { return test::xdmf_numbers(text); }

int check_references(const pugi::xml_node& root, const std::string& dir) {
  return test::check_xdmf_references(root, dir);
}

pugi::xml_node child_grid(const pugi::xml_node& parent, const std::string& name) {
  return parent.find_child_by_attribute("Grid", "Name", name.c_str());
}

}  // namespace

TEST(IoXdmf, IndexDescribesFramesAndResolves) {
  const std::string dir = test::scratch_dir("io_xdmf");
  Grid grid = test::sample_grid();
  OutputWriter writer(dir, false);
  writer.write_frame(test::sample_frame(grid, 0));
  writer.write_frame(test::sample_frame(grid, 10));

  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir + "/tephra.xdmf").c_str()));
  EXPECT_FALSE(std::filesystem::exists(dir + "/tephra.xdmf.tmp"));
  pugi::xml_node xdmf = doc.child("Xdmf");
  EXPECT_STREQ(xdmf.attribute("Version").value(), "3.0");
  pugi::xml_node series = xdmf.child("Domain").child("Grid");
  EXPECT_STREQ(series.attribute("GridType").value(), "Collection");
  EXPECT_STREQ(series.attribute("CollectionType").value(), "Temporal");

  std::vector<pugi::xml_node> frames;
  for (pugi::xml_node g : series.children("Grid")) frames.push_back(g);
  ASSERT_EQ(frames.size(), 2u);
  const double times[2] = {0.0, 10 * 1e-3};
  for (int n = 0; n < 2; ++n) {
    pugi::xml_node f = frames[n];
    EXPECT_STREQ(f.attribute("CollectionType").value(), "Spatial");
    EXPECT_EQ(f.child("Time").attribute("Value").as_double(), times[n]);

    // Interior mesh: cells (3,2,4) -> nodes "5 3 4" (k j i); origin and
    // spacing z y x.
    pugi::xml_node mesh = child_grid(f, "grid");
    ASSERT_TRUE(mesh);
    EXPECT_STREQ(mesh.child("Topology").attribute("TopologyType").value(), "3DCoRectMesh");
    EXPECT_STREQ(mesh.child("Topology").attribute("Dimensions").value(), "5 3 4");
    pugi::xml_node geo = mesh.child("Geometry");
    EXPECT_STREQ(geo.attribute("GeometryType").value(), "ORIGIN_DXDYDZ");
    EXPECT_EQ(numbers(geo.find_child_by_attribute("DataItem", "Name", "Origin").text().get()),
              (std::vector<double>{2.0, 0.5, -1.0}));
    EXPECT_EQ(numbers(geo.find_child_by_attribute("DataItem", "Name", "Spacing").text().get()),
              (std::vector<double>{0.125, 0.5, 0.25}));
    pugi::xml_node press = mesh.find_child_by_attribute("Attribute", "Name", "press_CC_mat0");
    EXPECT_STREQ(press.attribute("Center").value(), "Cell");
    EXPECT_STREQ(press.attribute("AttributeType").value(), "Scalar");
    EXPECT_STREQ(press.child("DataItem").attribute("Dimensions").value(), "4 2 3");
    pugi::xml_node vel = mesh.find_child_by_attribute("Attribute", "Name", "vel_CC_mat0");
    EXPECT_STREQ(vel.attribute("AttributeType").value(), "Vector");
    EXPECT_STREQ(vel.child("DataItem").attribute("Dimensions").value(), "4 2 3 3");
    pugi::xml_node gm = mesh.find_child_by_attribute("Attribute", "Name", "g.mass_mat0");
    EXPECT_STREQ(gm.attribute("Center").value(), "Node");
    EXPECT_STREQ(gm.child("DataItem").attribute("Dimensions").value(), "5 3 4");
    EXPECT_TRUE(mesh.find_child_by_attribute("Attribute", "Name", "press_CC_mat1"));
    const std::string ref = press.child("DataItem").text().get();
    EXPECT_EQ(ref, "frames/" + std::string(n == 0 ? "t00000" : "t00010") + ".h5:/grid/mat0/press_CC");

    // temp_CC includes the extra cells: its own mesh of (5,4,6) cells whose
    // origin is lower - extra*dx = (-1.25, 0, 1.875).
    pugi::xml_node extra = child_grid(f, "grid_with_extra_cells");
    ASSERT_TRUE(extra);
    EXPECT_STREQ(extra.child("Topology").attribute("Dimensions").value(), "7 5 6");
    EXPECT_EQ(numbers(extra.child("Geometry")
                          .find_child_by_attribute("DataItem", "Name", "Origin")
                          .text()
                          .get()),
              (std::vector<double>{1.875, 0.0, -1.25}));
    EXPECT_TRUE(extra.find_child_by_attribute("Attribute", "Name", "temp_CC_mat0"));

    // Particles: a Polyvertex per non-empty material, tensor stress.
    pugi::xml_node p0 = child_grid(f, "particles_mat0");
    ASSERT_TRUE(p0);
    EXPECT_STREQ(p0.child("Topology").attribute("TopologyType").value(), "Polyvertex");
    EXPECT_EQ(p0.child("Topology").attribute("NumberOfElements").as_int(), 5);
    EXPECT_STREQ(p0.child("Geometry").attribute("GeometryType").value(), "XYZ");
    EXPECT_STREQ(p0.child("Geometry").child("DataItem").attribute("Dimensions").value(), "5 3");
    pugi::xml_node stress = p0.find_child_by_attribute("Attribute", "Name", "p.stress");
    EXPECT_STREQ(stress.attribute("AttributeType").value(), "Tensor");
    EXPECT_STREQ(stress.child("DataItem").attribute("Dimensions").value(), "5 9");
    EXPECT_STREQ(p0.find_child_by_attribute("Attribute", "Name", "p.velocity")
                     .attribute("AttributeType")
                     .value(),
                 "Vector");
    EXPECT_TRUE(child_grid(f, "particles_mat1"));
    EXPECT_FALSE(child_grid(f, "particles_mat2"));  // zero particles
  }
  // 2 frames x (5 grid fields + 2 x (position, id) + 3 + 1 particle fields)
  EXPECT_EQ(check_references(doc, dir), 2 * (5 + 4 + 4));
}

TEST(IoXdmf, TruncateDropsLaterFramesFromIndex) {
  const std::string dir = test::scratch_dir("io_xdmf_truncate");
  Grid grid = test::sample_grid();
  {
    OutputWriter writer(dir, false);
    for (int s : {0, 10, 20}) writer.write_frame(test::sample_frame(grid, s));
  }
  OutputWriter restarted(dir, true);  // re-indexes the frames on disk
  restarted.truncate_after(10, 10e-3);
  EXPECT_FALSE(std::filesystem::exists(dir + "/frames/t00020.h5"));
  EXPECT_TRUE(std::filesystem::exists(dir + "/frames/t00010.h5"));
  pugi::xml_document doc;
  ASSERT_TRUE(doc.load_file((dir + "/tephra.xdmf").c_str()));
  EXPECT_EQ(doc.select_nodes("/Xdmf/Domain/Grid/Grid").size(), 2u);
  EXPECT_EQ(check_references(doc, dir), 2 * 13);
  restarted.write_frame(test::sample_frame(grid, 15));
  ASSERT_TRUE(doc.load_file((dir + "/tephra.xdmf").c_str()));
  EXPECT_EQ(doc.select_nodes("/Xdmf/Domain/Grid/Grid").size(), 3u);
}
