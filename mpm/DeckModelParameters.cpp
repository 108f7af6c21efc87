#include "mpm/DeckModelParameters.h"

namespace tephra {

const DeckNode& DeckModelParameters::at(const std::string& name) const {
  const DeckNode* c = node_.child(name);
  return c ? *c : node_;
}

bool DeckModelParameters::has(const std::string& name) const {
  used_.insert(name);
  return node_.has_child(name);
}

double DeckModelParameters::get_double(const std::string& name) const {
  used_.insert(name);
  return node_.get_double(name);
}

double DeckModelParameters::get_double(const std::string& name, double fallback) const {
  used_.insert(name);
  return node_.get_double(name, fallback);
}

bool DeckModelParameters::get_bool(const std::string& name, bool fallback) const {
  used_.insert(name);
  return node_.get_bool(name, fallback);
}

void DeckModelParameters::fail(const std::string& name, const std::string& message) const {
  at(name).fail(message);
}

void DeckModelParameters::missing_feature(const std::string& name, const std::string& what) const {
  at(name).missing_feature(what);
}

void DeckModelParameters::check_all_used(const std::string& model_name) const {
  for (const DeckNode& c : node_.children) {
    if (used_.count(c.name)) continue;
    std::string accepted;
    for (const auto& u : used_) accepted += (accepted.empty() ? "" : ", ") + u;
    c.fail("unknown parameter <" + c.name + "> of " + model_name + " (accepted: " + accepted + ")");
  }
}

}  // namespace tephra
