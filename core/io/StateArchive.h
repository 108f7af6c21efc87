#pragma once
// Named arrays that make up the restartable state of a run. Components put
// every array they need to continue bit for bit; the checkpoint writer stores
// them in HDF5 exactly (doubles as IEEE doubles, integers as int64).
#include <map>
#include <string>
#include <vector>

#include "core/base/Errors.h"

namespace tephra {

class StateArchive {
 public:
  void put(const std::string& name, std::vector<double> values) { doubles_[name] = std::move(values); }
  void put(const std::string& name, std::vector<long long> values) { ints_[name] = std::move(values); }
  void put_scalar(const std::string& name, double v) { doubles_[name] = {v}; }
  void put_int(const std::string& name, long long v) { ints_[name] = {v}; }

  const std::vector<double>& doubles(const std::string& name) const {
    auto it = doubles_.find(name);
    if (it == doubles_.end()) throw RuntimeFailure("checkpoint has no array '" + name + "'");
    return it->second;
  }
  const std::vector<long long>& ints(const std::string& name) const {
    auto it = ints_.find(name);
    if (it == ints_.end()) throw RuntimeFailure("checkpoint has no array '" + name + "'");
    return it->second;
  }
  double scalar(const std::string& name) const { return doubles(name).at(0); }
  long long integer(const std::string& name) const { return ints(name).at(0); }
  bool has(const std::string& name) const { return doubles_.count(name) || ints_.count(name); }

  const std::map<std::string, std::vector<double>>& all_doubles() const { return doubles_; }
  const std::map<std::string, std::vector<long long>>& all_ints() const { return ints_; }

 private:
  std::map<std::string, std::vector<double>> doubles_;
  std::map<std::string, std::vector<long long>> ints_;
};

}  // namespace tephra
