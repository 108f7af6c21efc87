#include "core/io/detail/H5.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <mutex>

#include "core/base/Errors.h"

namespace tephra::h5 {
namespace {

// HDF5 prints its error stack to stderr by default; our exceptions carry the
// file and object names instead, so the stack printing is switched off once.
void silence_hdf5() {
  static std::once_flag once;
  std::call_once(once, [] { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); });
}

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw RuntimeFailure(where + ": HDF5 " + what);
}

hid_t check(hid_t id, const std::string& where, const std::string& what) {
  if (id < 0) fail(where, what);
  return id;
}

void check_status(herr_t status, const std::string& where, const std::string& what) {
  if (status < 0) fail(where, what);
}

hsize_t element_count(const std::vector<hsize_t>& dims) {
  hsize_t n = 1;
  for (hsize_t d : dims) n *= d;
  return n;
}

void write_array(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims,
                 hid_t file_type, hid_t mem_type, const void* data, const std::string& where,
                 bool checksum) {
  const std::string obj = "dataset '" + name + "'";
  silence_hdf5();
  Handle space(check(H5Screate_simple(static_cast<int>(dims.size()), dims.data(), nullptr), where,
                     "cannot create dataspace for " + obj),
               Handle::Kind::Dataspace);
  Handle dcpl(check(H5Pcreate(H5P_DATASET_CREATE), where, "property list"), Handle::Kind::Plist);
  const hsize_t n = element_count(dims);
  if (checksum && n > 0) {
    // Chunks must not exceed the (fixed) extent: cap the slowest dimension so
    // a chunk holds at most ~64k elements.
    std::vector<hsize_t> chunk = dims;
    hsize_t inner = 1;
    for (size_t d = 1; d < dims.size(); ++d) inner *= dims[d];
    chunk[0] = std::max<hsize_t>(1, std::min<hsize_t>(dims[0], 65536 / std::max<hsize_t>(inner, 1)));
    check_status(H5Pset_chunk(dcpl.id(), static_cast<int>(chunk.size()), chunk.data()), where,
                 "cannot chunk " + obj);
    check_status(H5Pset_fletcher32(dcpl.id()), where, "cannot add checksum to " + obj);
  }
  Handle set(check(H5Dcreate2(parent, name.c_str(), file_type, space.id(), H5P_DEFAULT, dcpl.id(),
                              H5P_DEFAULT),
                   where, "cannot create " + obj),
             Handle::Kind::Dataset);
  if (n > 0)
    check_status(H5Dwrite(set.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data), where,
                 "cannot write " + obj);
}


H5T_class_t dataset_class(hid_t set, const std::string& name, const std::string& where) {
  Handle type(check(H5Dget_type(set), where, "cannot read the type of '" + name + "'"),
              Handle::Kind::Type);
  return H5Tget_class(type.id());
}

template <class T>
std::vector<T> read_array(hid_t parent, const std::string& name, hid_t mem_type,
                          H5T_class_t expected, const std::string& where) {
  Handle set = open_dataset(parent, name, where);
  if (dataset_class(set.id(), name, where) != expected)
    fail(where, "dataset '" + name + "' has the wrong number type");
  std::vector<T> out(element_count(dataset_dims(parent, name, where)));
  if (!out.empty())
    check_status(H5Dread(set.id(), mem_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, out.data()), where,
                 "cannot read dataset '" + name + "' (corrupt file?)");
  return out;
}

Handle open_attr(hid_t obj, const std::string& name, const std::string& where) {
  silence_hdf5();
  return Handle(check(H5Aopen(obj, name.c_str(), H5P_DEFAULT), where,
                      "has no attribute '" + name + "'"),
                Handle::Kind::Attribute);
}

void write_attr(hid_t obj, const std::string& name, hid_t file_type, hid_t mem_type, size_t n,
                const void* data, const std::string& where) {
  silence_hdf5();
  hsize_t dims[1] = {n};
  Handle space(check(H5Screate_simple(1, dims, nullptr), where, "dataspace"),
               Handle::Kind::Dataspace);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Handle attr(check(H5Acreate2(obj, name.c_str(), file_type, space.id(), H5P_DEFAULT, H5P_DEFAULT),
                    where, "cannot create attribute '" + name + "'"),
              Handle::Kind::Attribute);
  check_status(H5Awrite(attr.id(), mem_type, data), where, "cannot write attribute '" + name + "'");
}

template <class T>
std::vector<T> read_attr(hid_t obj, const std::string& name, hid_t mem_type,
                         const std::string& where) {
  Handle attr = open_attr(obj, name, where);
  Handle space(check(H5Aget_space(attr.id()), where, "attribute space"), Handle::Kind::Dataspace);
  hssize_t n = H5Sget_simple_extent_npoints(space.id());
  if (n < 0) fail(where, "attribute '" + name + "' has no extent");
  std::vector<T> out(static_cast<size_t>(n));
  if (n > 0)
    check_status(H5Aread(attr.id(), mem_type, out.data()), where,
                 "cannot read attribute '" + name + "'");
  return out;
}

}  // namespace

Handle open_dataset(hid_t parent, const std::string& name, const std::string& where) {
  silence_hdf5();
  return Handle(check(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), where,
                      "has no dataset '" + name + "'"),
                Handle::Kind::Dataset);
}

Handle& Handle::operator=(Handle&& o) noexcept {
  if (this != &o) {
    close();
    id_ = o.id_;
    kind_ = o.kind_;
    o.id_ = H5I_INVALID_HID;
  }
  return *this;
}

void Handle::close() {
  if (id_ < 0) return;
  switch (kind_) {
    case Kind::File: H5Fclose(id_); break;
    case Kind::Group: H5Gclose(id_); break;
    case Kind::Dataset: H5Dclose(id_); break;
    case Kind::Dataspace: H5Sclose(id_); break;
    case Kind::Attribute: H5Aclose(id_); break;
    case Kind::Plist: H5Pclose(id_); break;
    case Kind::Type: H5Tclose(id_); break;
  }
  id_ = H5I_INVALID_HID;
}

Handle create_file(const std::string& path) {
  silence_hdf5();
  return Handle(check(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), path,
                      "cannot create the file"),
                Handle::Kind::File);
}

Handle open_file_readonly(const std::string& path) {
  silence_hdf5();
  if (!std::filesystem::exists(path)) throw RuntimeFailure(path + ": no such file");
  return Handle(check(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), path,
                      "cannot open the file (not HDF5 or truncated)"),
                Handle::Kind::File);
}

void flush(const Handle& file, const std::string& where) {
  check_status(H5Fflush(file.id(), H5F_SCOPE_GLOBAL), where, "cannot flush the file");
}

Handle create_group(hid_t parent, const std::string& name, const std::string& where) {
  silence_hdf5();
  return Handle(check(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
                      where, "cannot create group '" + name + "'"),
                Handle::Kind::Group);
}

Handle open_group(hid_t parent, const std::string& name, const std::string& where) {
  silence_hdf5();
  return Handle(check(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), where,
                      "has no group '" + name + "'"),
                Handle::Kind::Group);
}

bool exists(hid_t parent, const std::string& name) {
  silence_hdf5();
  return H5Lexists(parent, name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<std::string> children(hid_t group, const std::string& where) {
  silence_hdf5();
  std::vector<std::string> names;
  auto collect = [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
    static_cast<std::vector<std::string>*>(out)->push_back(name);
    return 0;
  };
  check_status(H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, nullptr, collect, &names), where,
               "cannot list a group");
  std::sort(names.begin(), names.end());
  return names;
}

void write_doubles(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims,
                   const double* data, const std::string& where, bool checksum) {
  write_array(parent, name, dims, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, data, where, checksum);
}

void write_int64s(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims,
                  const long long* data, const std::string& where, bool checksum) {
  write_array(parent, name, dims, H5T_STD_I64LE, H5T_NATIVE_LLONG, data, where, checksum);
}

std::vector<hsize_t> dataset_dims(hid_t parent, const std::string& name, const std::string& where) {
  Handle set = open_dataset(parent, name, where);
  Handle space(check(H5Dget_space(set.id()), where, "dataspace of '" + name + "'"),
               Handle::Kind::Dataspace);
  int rank = H5Sget_simple_extent_ndims(space.id());
  if (rank < 0) fail(where, "dataset '" + name + "' has no extent");
  std::vector<hsize_t> dims(static_cast<size_t>(rank));
  if (rank > 0) H5Sget_simple_extent_dims(space.id(), dims.data(), nullptr);
  return dims;
}

bool dataset_is_integer(hid_t parent, const std::string& name, const std::string& where) {
  Handle set = open_dataset(parent, name, where);
  return dataset_class(set.id(), name, where) == H5T_INTEGER;
}

std::vector<double> read_doubles(hid_t parent, const std::string& name, const std::string& where) {
  return read_array<double>(parent, name, H5T_NATIVE_DOUBLE, H5T_FLOAT, where);
}

std::vector<long long> read_int64s(hid_t parent, const std::string& name,
                                   const std::string& where) {
  return read_array<long long>(parent, name, H5T_NATIVE_LLONG, H5T_INTEGER, where);
}

void set_attr_doubles(hid_t obj, const std::string& name, const std::vector<double>& v,
                      const std::string& where) {
  write_attr(obj, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, v.size(), v.data(), where);
}

void set_attr_int64s(hid_t obj, const std::string& name, const std::vector<long long>& v,
                     const std::string& where) {
  write_attr(obj, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, v.size(), v.data(), where);
}

void set_attr_string(hid_t obj, const std::string& name, const std::string& v,
                     const std::string& where) {
  // A fixed-length string type of exactly the text's size (h5dump shows it).
  silence_hdf5();
  Handle type(check(H5Tcopy(H5T_C_S1), where, "string type"), Handle::Kind::Type);
  check_status(H5Tset_size(type.id(), std::max<size_t>(v.size(), 1)), where, "string size");
  Handle space(check(H5Screate(H5S_SCALAR), where, "dataspace"), Handle::Kind::Dataspace);
  if (H5Aexists(obj, name.c_str()) > 0) H5Adelete(obj, name.c_str());
  Handle attr(check(H5Acreate2(obj, name.c_str(), type.id(), space.id(), H5P_DEFAULT, H5P_DEFAULT),
                    where, "cannot create attribute '" + name + "'"),
              Handle::Kind::Attribute);
  std::string padded = v.empty() ? std::string(1, '\0') : v;
  check_status(H5Awrite(attr.id(), type.id(), padded.data()), where,
               "cannot write attribute '" + name + "'");
}

std::vector<double> attr_doubles(hid_t obj, const std::string& name, const std::string& where) {
  return read_attr<double>(obj, name, H5T_NATIVE_DOUBLE, where);
}

std::vector<long long> attr_int64s(hid_t obj, const std::string& name, const std::string& where) {
  return read_attr<long long>(obj, name, H5T_NATIVE_LLONG, where);
}

std::string attr_string(hid_t obj, const std::string& name, const std::string& where) {
  Handle attr = open_attr(obj, name, where);
  Handle type(check(H5Aget_type(attr.id()), where, "attribute type"), Handle::Kind::Type);
  if (H5Tget_class(type.id()) != H5T_STRING || H5Tis_variable_str(type.id()) > 0)
    fail(where, "attribute '" + name + "' is not a fixed-length string");
  size_t size = H5Tget_size(type.id());
  std::string out(size, '\0');
  check_status(H5Aread(attr.id(), type.id(), out.data()), where,
               "cannot read attribute '" + name + "'");
  out.resize(std::strlen(out.c_str()));
  return out;
}

bool has_attr(hid_t obj, const std::string& name) {
  silence_hdf5();
  return H5Aexists(obj, name.c_str()) > 0;
}

}  // namespace tephra::h5
