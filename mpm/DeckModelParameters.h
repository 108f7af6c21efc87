#pragma once
// ModelParameters read from a deck element (e.g. <constitutive_model>): the
// parameters are its children. Failures are DeckError / MissingFeature at the
// child (or at the element when the child is absent). Remembers every name a
// model asked for, so that check_all_used() can reject children no model reads.
#include <map>
#include <memory>
#include <set>
#include <string>

#include "core/deck/DeckNode.h"
#include "models/ModelParameters.h"

namespace tephra {

class DeckModelParameters final : public ModelParameters {
 public:
  explicit DeckModelParameters(const DeckNode& node) : node_(node) {}

  bool has(const std::string& name) const override;
  double get_double(const std::string& name) const override;
  double get_double(const std::string& name, double fallback) const override;
  bool get_bool(const std::string& name, bool fallback) const override;
  std::string get_string(const std::string& name, const std::string& fallback) const override;
  std::string file_path(const std::string& name) const override;
  [[noreturn]] void fail(const std::string& name, const std::string& message) const override;
  [[noreturn]] void missing_feature(const std::string& name, const std::string& what) const override;
  const ModelParameters* block(const std::string& name) const override;
  std::string type_attribute() const override;
  double enclosing_double(const std::string& name, double fallback) const override;
  bool mpm_flag(const std::string& name, bool fallback) const override;

  // DeckError at the first child that no get/has/block call asked for, also
  // inside every block a model opened.
  void check_all_used(const std::string& model_name) const;

 private:
  const DeckNode& at(const std::string& name) const;
  const DeckNode& node_;
  mutable std::set<std::string> used_;
  mutable std::map<std::string, std::unique_ptr<DeckModelParameters>> blocks_;
};

}  // namespace tephra
