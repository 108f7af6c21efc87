#pragma once
// Thin RAII layer over the HDF5 C API for the writers and readers of core/io.
// Private to core/io: it includes hdf5.h, so no public header may include it.
// Every failing call throws RuntimeFailure naming the file and the object, and
// HDF5's own error stack printing is switched off (our message replaces it).
#include <hdf5.h>

#include <string>
#include <vector>

namespace tephra::h5 {

// Owns one hid_t and closes it with the matching H5?close.
class Handle {
 public:
  enum class Kind { File, Group, Dataset, Dataspace, Attribute, Plist, Type };
  Handle() = default;
  Handle(hid_t id, Kind kind) : id_(id), kind_(kind) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& o) noexcept : id_(o.id_), kind_(o.kind_) { o.id_ = H5I_INVALID_HID; }
  Handle& operator=(Handle&& o) noexcept;
  ~Handle() { close(); }
  hid_t id() const { return id_; }
  void close();

 private:
  hid_t id_ = H5I_INVALID_HID;
  Kind kind_ = Kind::File;
};

// Files. `where` (the file name) goes into every error message.
Handle create_file(const std::string& path);           // truncates
Handle open_file_readonly(const std::string& path);     // RuntimeFailure if absent/not HDF5
void flush(const Handle& file, const std::string& where);

Handle create_group(hid_t parent, const std::string& name, const std::string& where);
Handle open_group(hid_t parent, const std::string& name, const std::string& where);
bool exists(hid_t parent, const std::string& name);     // direct child link only
std::vector<std::string> children(hid_t group, const std::string& where);  // names, sorted

// Datasets of doubles or int64 with explicit dims (row-major, last fastest).
// `checksum` adds HDF5's Fletcher-32 filter (needs chunked layout), so a
// flipped bit is detected on read.
void write_doubles(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims,
                   const double* data, const std::string& where, bool checksum = false);
void write_int64s(hid_t parent, const std::string& name, const std::vector<hsize_t>& dims,
                  const long long* data, const std::string& where, bool checksum = false);
Handle open_dataset(hid_t parent, const std::string& name, const std::string& where);  // for its attrs
std::vector<hsize_t> dataset_dims(hid_t parent, const std::string& name, const std::string& where);
bool dataset_is_integer(hid_t parent, const std::string& name, const std::string& where);
std::vector<double> read_doubles(hid_t parent, const std::string& name, const std::string& where);
std::vector<long long> read_int64s(hid_t parent, const std::string& name, const std::string& where);

// Small attributes on any object (file, group, dataset).
void set_attr_doubles(hid_t obj, const std::string& name, const std::vector<double>& v,
                      const std::string& where);
void set_attr_int64s(hid_t obj, const std::string& name, const std::vector<long long>& v,
                     const std::string& where);
void set_attr_string(hid_t obj, const std::string& name, const std::string& v,
                     const std::string& where);
std::vector<double> attr_doubles(hid_t obj, const std::string& name, const std::string& where);
std::vector<long long> attr_int64s(hid_t obj, const std::string& name, const std::string& where);
std::string attr_string(hid_t obj, const std::string& name, const std::string& where);
bool has_attr(hid_t obj, const std::string& name);

}  // namespace tephra::h5
