// See ArchiveNames.h.
#include "core/io/detail/ArchiveNames.h"

#include "core/base/Errors.h"

namespace tephra::archive_names {

// HDF5 link names cannot contain '/' and cannot be "." : escape them (and
// the escape character) percent-style so any archive name survives.
std::string escape(const std::string& name) {
  std::string out;
  for (size_t i = 0; i < name.size(); ++i) {
    const char c = name[i];
    if (c == '%') out += "%25";
    else if (c == '/') out += "%2F";
    else if (c == '.' && i == 0) out += "%2E";
    else out += c;
  }
  return out;
}

std::string unescape(const std::string& name, const std::string& where) {
  std::string out;
  for (size_t i = 0; i < name.size(); ++i) {
    if (name[i] != '%') {
      out += name[i];
      continue;
    }
    const std::string code = name.substr(i + 1, 2);
    if (code == "25") out += '%';
    else if (code == "2F") out += '/';
    else if (code == "2E") out += '.';
    else throw RuntimeFailure(where + ": bad escaped array name '" + name + "'");
    i += 2;
  }
  return out;
}

}  // namespace tephra::archive_names
