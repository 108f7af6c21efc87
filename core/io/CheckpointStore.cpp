// CheckpointStore: the restartable state as HDF5 files, bit for bit.
// Doubles are stored as IEEE binary64 little-endian (H5T_IEEE_F64LE) and read
// back into native doubles, integers as int64 (H5T_STD_I64LE): on any
// little-endian IEEE machine both conversions are the identity, so a restart
// continues with exactly the bits that were saved.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "core/base/Errors.h"
#include "core/io/OutputWriter.h"
#include "core/io/StateArchive.h"
#include "core/io/detail/Files.h"
#include "core/io/detail/H5.h"

namespace tephra {
namespace fs = std::filesystem;
namespace {

const char* kFormat = "tephra-checkpoint-1";

// HDF5 link names cannot contain '/' and cannot be "." : escape them (and
// the escape character) percent-style so any archive name survives.
std::string escape_name(const std::string& name) {
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

std::string unescape_name(const std::string& name, const std::string& where) {
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

int parse_checkpoint_name(const std::string& name) {
  // c + digits + .h5
  if (name.size() < 5 || name[0] != 'c' || name.compare(name.size() - 3, 3, ".h5") != 0) return -1;
  const std::string digits = name.substr(1, name.size() - 4);
  if (digits.empty() || digits.size() > 9) return -1;
  for (char c : digits)
    if (c < '0' || c > '9') return -1;
  return std::stoi(digits);
}

}  // namespace

CheckpointStore::CheckpointStore(const std::string& output_dir, int cycle)
    : dir_((fs::path(output_dir) / "checkpoints").string()), cycle_(cycle) {
  if (cycle < 1)
    throw std::invalid_argument("checkpoint cycle must be at least 1, got " + std::to_string(cycle));
  std::error_code ec;
  fs::create_directories(dir_, ec);
  if (ec) throw RuntimeFailure(dir_ + ": cannot create directory (" + ec.message() + ")");
}

std::string CheckpointStore::path(int step) const {
  char buf[32];
  std::snprintf(buf, sizeof buf, "c%05d.h5", step);
  return (fs::path(dir_) / buf).string();
}

void CheckpointStore::write(int step, const StateArchive& state) {
  const std::string final_path = path(step);
  const std::string tmp = files::tmp_name(final_path);
  try {
    h5::Handle file = h5::create_file(tmp);
    h5::set_attr_string(file.id(), "format", kFormat, tmp);
    h5::set_attr_int64s(file.id(), "step", {step}, tmp);
    h5::Handle d = h5::create_group(file.id(), "doubles", tmp);
    for (const auto& [name, v] : state.all_doubles())
      h5::write_doubles(d.id(), escape_name(name), {hsize_t(v.size())}, v.data(), tmp, true);
    h5::Handle i = h5::create_group(file.id(), "ints", tmp);
    for (const auto& [name, v] : state.all_ints())
      h5::write_int64s(i.id(), escape_name(name), {hsize_t(v.size())}, v.data(), tmp, true);
    h5::flush(file, tmp);
  } catch (...) {
    files::remove_if_present(tmp);
    throw;
  }
  files::sync_and_rename(tmp, final_path);

  // Retention: drop checkpoints newer than this one (an abandoned
  // continuation), then the oldest until `cycle` remain.
  std::vector<int> all = steps();
  std::vector<int> kept;
  for (int s : all) {
    if (s > step) files::remove_if_present(path(s));
    else kept.push_back(s);
  }
  for (size_t n = 0; n + cycle_ < kept.size(); ++n) files::remove_if_present(path(kept[n]));
}

std::vector<int> CheckpointStore::steps() const {
  std::vector<int> out;
  for (const auto& e : fs::directory_iterator(dir_)) {
    const int s = parse_checkpoint_name(e.path().filename().string());
    if (s >= 0 && e.is_regular_file()) out.push_back(s);
  }
  std::sort(out.begin(), out.end());
  return out;
}

StateArchive CheckpointStore::read(int step) const {
  const std::string p = path(step);
  h5::Handle file = h5::open_file_readonly(p);
  if (!h5::has_attr(file.id(), "format") || h5::attr_string(file.id(), "format", p) != kFormat)
    throw RuntimeFailure(p + ": not a Tephra checkpoint (format attribute missing or unknown)");
  StateArchive out;
  h5::Handle d = h5::open_group(file.id(), "doubles", p);
  for (const std::string& name : h5::children(d.id(), p))
    out.put(unescape_name(name, p), h5::read_doubles(d.id(), name, p));
  h5::Handle i = h5::open_group(file.id(), "ints", p);
  for (const std::string& name : h5::children(i.id(), p))
    out.put(unescape_name(name, p), h5::read_int64s(i.id(), name, p));
  return out;
}

}  // namespace tephra
