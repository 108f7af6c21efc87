#pragma once
// Names of StateArchive arrays as HDF5 link names (checkpoint files, one-file
// and per-rank): HDF5 link names cannot contain '/' and cannot be ".", so
// '%', '/' and a leading '.' are written percent-style as %25, %2F and %2E.
#include <string>

namespace tephra::archive_names {

std::string escape(const std::string& name);
// `where` (the file) goes into the error for a bad escape.
std::string unescape(const std::string& name, const std::string& where);

}  // namespace tephra::archive_names
