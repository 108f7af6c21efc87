#include "models/VectorParameter.h"

#include <sstream>

namespace tephra {

std::optional<Eigen::Vector3d> optional_vector_parameter(const ModelParameters& params, const std::string& name) {
  std::string t = params.get_string(name, "");
  if (t.find_first_not_of(" \t\n") == std::string::npos) return std::nullopt;
  for (char& c : t)
    if (c == '[' || c == ']' || c == ',') c = ' ';
  std::istringstream in(t);
  Eigen::Vector3d v;
  std::string rest;
  if (!(in >> v[0] >> v[1] >> v[2]) || (in >> rest) || !v.allFinite())
    params.fail(name, name + " must be a vector [x, y, z] of three finite numbers");
  return v;
}

Eigen::Vector3d vector_parameter(const ModelParameters& params, const std::string& name) {
  const std::optional<Eigen::Vector3d> v = optional_vector_parameter(params, name);
  if (!v) params.fail(name, name + " is required: a vector [x, y, z]");
  return *v;
}

}  // namespace tephra
