#include "core/io/detail/Files.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/base/Errors.h"

namespace tephra::files {
namespace {

[[noreturn]] void fail(const std::string& path, const std::string& what) {
  throw RuntimeFailure(path + ": " + what + " (" + std::strerror(errno) + ")");
}

void write_fully(int fd, const std::string& data, const std::string& path) {
  size_t done = 0;
  while (done < data.size()) {
    ssize_t n = ::write(fd, data.data() + done, data.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      ::close(fd);
      fail(path, "cannot write");
    }
    done += static_cast<size_t>(n);
  }
}

}  // namespace

std::string tmp_name(const std::string& path) { return path + ".tmp"; }

void write_atomic(const std::string& path, const std::string& content) {
  const std::string tmp = tmp_name(path);
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail(tmp, "cannot create");
  write_fully(fd, content, tmp);
  if (::close(fd) != 0) fail(tmp, "cannot close");
  sync_and_rename(tmp, path);
}

void sync_and_rename(const std::string& tmp, const std::string& path) {
  int fd = ::open(tmp.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) fail(tmp, "cannot reopen for fsync");
  ::fsync(fd);
  ::close(fd);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail(path, "cannot rename " + tmp + " to it");
}

void remove_if_present(const std::string& path) {
  std::error_code ec;
  std::filesystem::remove(path, ec);
  if (ec) throw RuntimeFailure(path + ": cannot remove (" + ec.message() + ")");
}

void append_row(const std::string& path, const std::string& row) {
  int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (fd < 0) fail(path, "cannot open for append");
  ssize_t n;
  do {
    n = ::write(fd, row.data(), row.size());
  } while (n < 0 && errno == EINTR);
  if (n != static_cast<ssize_t>(row.size())) {
    ::close(fd);
    fail(path, "cannot append a row");
  }
  if (::close(fd) != 0) fail(path, "cannot close");
}

std::string read_all(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw RuntimeFailure(path + ": cannot open for reading");
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::vector<std::string> read_complete_lines(const std::string& path) {
  const std::string text = read_all(path);
  std::vector<std::string> lines;
  size_t start = 0;
  for (size_t nl; (nl = text.find('\n', start)) != std::string::npos; start = nl + 1)
    lines.push_back(text.substr(start, nl - start));
  return lines;
}

}  // namespace tephra::files
