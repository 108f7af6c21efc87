#include "core/io/Reductions.h"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include "core/base/Errors.h"
#include "core/io/detail/Files.h"

namespace tephra {

std::string reduction_file(const std::string& dir, const std::string& label) {
  return (std::filesystem::path(dir) / (label + ".dat")).string();
}

std::string format_reduction_row(double time, const std::vector<double>& values) {
  std::string row;
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", time);
  row += buf;
  for (double v : values) {
    std::snprintf(buf, sizeof buf, " %.17g", v);
    row += buf;
  }
  return row + "\n";
}

std::vector<ReductionRow> read_reduction_file(const std::string& path) {
  std::vector<ReductionRow> rows;
  const std::vector<std::string> lines = files::read_complete_lines(path);
  for (size_t n = 0; n < lines.size(); ++n) {
    const char* p = lines[n].c_str();
    std::vector<double> numbers;
    while (true) {
      while (*p == ' ' || *p == '\t' || *p == '\r') ++p;
      if (!*p) break;
      char* end = nullptr;
      errno = 0;
      double v = std::strtod(p, &end);
      if (end == p)
        throw RuntimeFailure(path + ":" + std::to_string(n + 1) + ": not a number: '" + p + "'");
      numbers.push_back(v);
      p = end;
    }
    if (numbers.empty()) continue;  // blank line
    if (numbers.size() < 2)
      throw RuntimeFailure(path + ":" + std::to_string(n + 1) + ": row has a time but no value");
    if (!rows.empty() && rows.front().values.size() != numbers.size() - 1)
      throw RuntimeFailure(path + ":" + std::to_string(n + 1) + ": row has " +
                           std::to_string(numbers.size()) + " numbers, the first row " +
                           std::to_string(rows.front().values.size() + 1));
    rows.push_back({numbers[0], std::vector<double>(numbers.begin() + 1, numbers.end())});
  }
  return rows;
}

std::vector<std::string> read_reduction_labels(const std::string& dir) {
  const std::string path = (std::filesystem::path(dir) / kReductionManifest).string();
  if (!std::filesystem::exists(path)) return {};
  std::vector<std::string> labels;
  for (const std::string& line : files::read_complete_lines(path))
    if (!line.empty()) labels.push_back(line);
  return labels;
}

}  // namespace tephra
