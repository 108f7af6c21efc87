#pragma once
// File-system helpers for the output directory. Whole files are written
// under `<name>.tmp`, flushed to disk (fsync) and renamed over `<name>`:
// rename(2) is atomic on POSIX, so a reader (or a run killed mid-write) sees
// either the old file or the new one, never a half-written one.
#include <string>
#include <vector>

namespace tephra::files {

std::string tmp_name(const std::string& path);          // path + ".tmp"
void write_atomic(const std::string& path, const std::string& content);
void sync_and_rename(const std::string& tmp, const std::string& path);  // fsync tmp, rename
void remove_if_present(const std::string& path);

// Writes `path` through its tmp name: write(tmp) creates and fills the tmp
// file; if it throws, the tmp file is removed and the exception passes on,
// else the tmp file is synced and renamed over `path`.
template <class Write>
void write_via_tmp(const std::string& path, Write&& write) {
  const std::string tmp = tmp_name(path);
  try {
    write(tmp);
  } catch (...) {
    remove_if_present(tmp);
    throw;
  }
  sync_and_rename(tmp, path);
}

// Appends `row` (which must end with '\n') to `path` with one write(2) on an
// O_APPEND descriptor: the row lands whole at the end of the file. A process
// killed before the call leaves no trace of the row; only a kernel or power
// failure during the call could tear it, and read_complete_lines() drops
// such a torn (newline-less) tail.
void append_row(const std::string& path, const std::string& row);

// The newline-terminated lines of a text file (a trailing fragment without
// '\n' is ignored, see append_row). RuntimeFailure if it cannot be read.
std::vector<std::string> read_complete_lines(const std::string& path);
std::string read_all(const std::string& path);

}  // namespace tephra::files
