#pragma once
// Assembly of the composed metal models (elastic_plastic, elastic_plastic_hp)
// from the sub-model blocks of their <constitutive_model> element: each block
// <name type="key"> is created by its family's registry (models/plasticity/);
// an absent block takes the default key Vaango's factories use. Only the two
// composed models include this header.
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "models/ModelParameters.h"
#include "models/plasticity/SubModelTable.h"

namespace tephra::assembly {

inline std::string join_keys(const std::vector<std::string>& keys) {
  std::string s;
  for (const auto& k : keys) s += (s.empty() ? "" : ", ") + k;
  return s;
}

// The parameters of an absent block: no children; failures name the block.
class AbsentBlock final : public ModelParameters {
 public:
  AbsentBlock(const ModelParameters& parent, std::string name) : parent_(parent), name_(std::move(name)) {}
  bool has(const std::string&) const override { return false; }
  double get_double(const std::string& n) const override { fail(n, "required"); }
  double get_double(const std::string&, double fallback) const override { return fallback; }
  bool get_bool(const std::string&, bool fallback) const override { return fallback; }
  [[noreturn]] void fail(const std::string& n, const std::string& m) const override {
    parent_.fail(name_, "default <" + name_ + ">: " + n + ": " + m);
    throw std::logic_error("ModelParameters::fail returned");  // its contract is to throw
  }
  [[noreturn]] void missing_feature(const std::string& n, const std::string& m) const override {
    parent_.missing_feature(name_, n + ": " + m);
    throw std::logic_error("ModelParameters::missing_feature returned");  // its contract is to throw
  }

 private:
  const ModelParameters& parent_;
  std::string name_;
};

// Creates the sub-model of block `name` with the family's registry `table`;
// `fallback` is the key used when the block is absent ("" = the block is
// required). `model` names the composed model in messages.
template <class Model, class Create>
std::shared_ptr<const Model> sub_model(const ModelParameters& params, const std::string& model,
                                       const std::string& name, const std::vector<SubModelEntry<Model>>& table,
                                       const std::string& fallback, const SubModelContext& ctx, Create create) {
  const ModelParameters* b = params.block(name);
  if (!b) {
    if (fallback.empty()) params.fail(name, model + " requires <" + name + " type=\"...\">");
    return std::shared_ptr<const Model>(create(fallback, AbsentBlock(params, name), ctx));
  }
  const std::string key = b->type_attribute();
  if (key.empty()) params.fail(name, "<" + name + "> needs a type attribute (" + join_keys(sub_model_keys(table)) + ")");
  auto m = create(key, *b, ctx);
  if (!m) params.fail(name, "unknown " + name + " type '" + key + "' (valid: " + join_keys(sub_model_keys(table)) + ")");
  return std::shared_ptr<const Model>(std::move(m));
}

// The type of an optional block ("" when absent).
inline std::string block_type(const ModelParameters& params, const std::string& name) {
  const ModelParameters* b = params.block(name);
  return b ? b->type_attribute() : std::string();
}

}  // namespace tephra::assembly
