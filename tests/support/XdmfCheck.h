#pragma once
// Checks on a written tephra.xdmf shared by tests/unit/test_io_xdmf.cpp and
// the rank-file tests: every Format="HDF" DataItem "file:/path" must name an
// existing HDF5 dataset whose dimensions are the declared ones.
#include <gtest/gtest.h>
#include <hdf5.h>

#include <pugixml.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace tephra::test {

inline std::vector<double> xdmf_numbers(const std::string& text) {
  std::istringstream in(text);
  std::vector<double> v;
  for (double x; in >> x;) v.push_back(x);
  return v;
}

// Dimensions of `dataset` in `file`; empty when the file or dataset is absent.
inline std::vector<hsize_t> h5_dims(const std::string& file, const std::string& dataset) {
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  hid_t f = H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (f < 0) return {};
  std::vector<hsize_t> dims;
  hid_t d = H5Dopen2(f, dataset.c_str(), H5P_DEFAULT);
  if (d >= 0) {
    hid_t s = H5Dget_space(d);
    dims.resize(H5Sget_simple_extent_ndims(s));
    H5Sget_simple_extent_dims(s, dims.data(), nullptr);
    H5Sclose(s);
    H5Dclose(d);
  }
  H5Fclose(f);
  return dims;
}

// Every Format="HDF" DataItem under `root`: "file:/path" exists (relative to
// `dir`), with the declared dims. Returns how many were checked; the files
// referenced go to `files` when given.
inline int check_xdmf_references(const pugi::xml_node& root, const std::string& dir,
                                 std::set<std::string>* files = nullptr) {
  int count = 0;
  for (const pugi::xpath_node& x : root.select_nodes("//DataItem[@Format='HDF']")) {
    const std::string ref = x.node().text().get();
    const size_t colon = ref.find(':');
    EXPECT_NE(colon, std::string::npos) << ref;
    if (colon == std::string::npos) continue;
    if (files) files->insert(ref.substr(0, colon));
    const std::vector<hsize_t> dims = h5_dims(dir + "/" + ref.substr(0, colon), ref.substr(colon + 1));
    std::vector<double> declared = xdmf_numbers(x.node().attribute("Dimensions").value());
    EXPECT_EQ(dims.size(), declared.size()) << ref;
    for (size_t n = 0; n < std::min(dims.size(), declared.size()); ++n)
      EXPECT_EQ(double(dims[n]), declared[n]) << ref;
    EXPECT_STREQ(x.node().attribute("Precision").value(), "8");
    ++count;
  }
  return count;
}

}  // namespace tephra::test
