#include "mpm/DeckModelParameters.h"

#include <filesystem>

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

std::string DeckModelParameters::get_string(const std::string& name, const std::string& fallback) const {
  used_.insert(name);
  const DeckNode* c = node_.child(name);
  return c ? c->text : fallback;
}

std::string DeckModelParameters::file_path(const std::string& name) const {
  used_.insert(name);
  const DeckNode* c = node_.child(name);
  if (!c) return {};
  const std::filesystem::path path(c->text);
  if (path.is_relative()) {
    const std::filesystem::path beside = std::filesystem::path(c->file).parent_path() / path;
    if (std::filesystem::exists(beside)) return beside.string();
  }
  return c->text;
}

void DeckModelParameters::fail(const std::string& name, const std::string& message) const {
  at(name).fail(message);
}

void DeckModelParameters::missing_feature(const std::string& name, const std::string& what) const {
  at(name).missing_feature(what);
}

const ModelParameters* DeckModelParameters::block(const std::string& name) const {
  used_.insert(name);
  auto it = blocks_.find(name);
  if (it != blocks_.end()) return it->second.get();
  const DeckNode* c = node_.child(name);
  if (!c) return nullptr;
  return blocks_.emplace(name, std::make_unique<DeckModelParameters>(*c)).first->second.get();
}

std::string DeckModelParameters::type_attribute() const { return node_.attribute("type").value_or(""); }

double DeckModelParameters::enclosing_double(const std::string& name, double fallback) const {
  return node_.parent ? node_.parent->get_double(name, fallback) : fallback;
}

bool DeckModelParameters::mpm_flag(const std::string& name, bool fallback) const {
  const DeckNode* root = &node_;
  while (root->parent) root = root->parent;
  const DeckNode* mpm = root->child("MPM");
  return mpm ? mpm->get_bool(name, fallback) : fallback;
}

void DeckModelParameters::check_all_used(const std::string& model_name) const {
  for (const auto& [name, b] : blocks_) b->check_all_used(model_name + " <" + name + ">");
  for (const DeckNode& c : node_.children) {
    if (used_.count(c.name)) continue;
    std::string accepted;
    for (const auto& u : used_) accepted += (accepted.empty() ? "" : ", ") + u;
    c.fail("unknown parameter <" + c.name + "> of " + model_name + " (accepted: " + accepted + ")");
  }
}

}  // namespace tephra
