#pragma once
// What a model creator reads its parameters from. models/ depends on Eigen
// only (DESIGN.md §1), so it cannot see the deck tree; the driver wraps the
// deck element (e.g. <constitutive_model>) in an implementation of this
// interface whose failures throw DeckError / MissingFeature located at the
// element. Every name a creator reads is marked as used, so the driver can
// reject unknown children afterwards (no silently ignored parameters).
#include <string>

namespace tephra {

class ModelParameters {
 public:
  virtual ~ModelParameters() = default;
  virtual bool has(const std::string& name) const = 0;
  virtual double get_double(const std::string& name) const = 0;  // required
  virtual double get_double(const std::string& name, double fallback) const = 0;
  virtual bool get_bool(const std::string& name, bool fallback) const = 0;
  // A text value (trimmed), `fallback` when absent. Implementations without
  // text values (test maps) return the fallback.
  virtual std::string get_string(const std::string& /*name*/, const std::string& fallback) const { return fallback; }
  // The text of parameter `name` read as a file path (tabular_eos <filename>): a
  // relative path is taken beside the deck file when a file is there, else as
  // given (the working directory), as <prescribed_deformation_file>. Without a
  // deck (test maps) the text itself.
  virtual std::string file_path(const std::string& name) const { return get_string(name, ""); }
  // Invalid value: throws (DeckError at the parameter's element).
  [[noreturn]] virtual void fail(const std::string& name, const std::string& message) const = 0;
  // Valid input that asks for something not implemented (MissingFeature).
  [[noreturn]] virtual void missing_feature(const std::string& name, const std::string& what) const = 0;

  // ---- nested sub-model blocks (composed models such as elastic_plastic_hp):
  // a child element <name type="key"> whose own children are its parameters.
  // The block, or nullptr when absent; owned by (and living as long as) this
  // object; marks `name` as used. Implementations without blocks return nullptr.
  virtual const ModelParameters* block(const std::string& /*name*/) const { return nullptr; }
  // This element's `type` attribute ("" when it has none): a block's sub-model key.
  virtual std::string type_attribute() const { return {}; }
  // A value of the ENCLOSING element (the <material> around <constitutive_model>:
  // melt_temp, specific_heat, ...), which Vaango hands to sub-models as defaults;
  // `fallback` when absent or when there is no enclosing element.
  virtual double enclosing_double(const std::string& /*name*/, double fallback) const { return fallback; }
  // A boolean flag of the deck's top-level <MPM> section (e.g. <DoThermalExpansion>, Vaango
  // MPMFlags), `fallback` when absent or when the parameters do not come from a deck.
  virtual bool mpm_flag(const std::string& /*name*/, bool fallback) const { return fallback; }
};

}  // namespace tephra
