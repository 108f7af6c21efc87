#include "core/sim/RunParameters.h"

#include "core/deck/DeckNode.h"

namespace tephra {

namespace {

double positive(const DeckNode& section, const std::string& name) {
  const DeckNode& n = section.require_child(name);
  double v = n.as_double();
  if (!(v > 0.0)) n.fail("must be positive, found " + n.text);
  return v;
}

double non_negative(const DeckNode& section, const std::string& name, double fallback) {
  const DeckNode* n = section.child(name);
  if (!n) return fallback;
  double v = n->as_double();
  if (v < 0.0) n->fail("must not be negative, found " + n->text);
  return v;
}

}  // namespace

TimeParameters read_time_parameters(const DeckNode& t) {
  TimeParameters p;
  p.max_time = positive(t, "maxTime");
  p.init_time = non_negative(t, "initTime", 0.0);
  if (p.init_time >= p.max_time)
    t.require_child("initTime").fail("initTime must be smaller than maxTime");
  p.delt_min = non_negative(t, "delt_min", 0.0);
  p.delt_max = positive(t, "delt_max");
  if (p.delt_min > p.delt_max) t.require_child("delt_min").fail("delt_min exceeds delt_max");
  p.timestep_multiplier = positive(t, "timestep_multiplier");
  if (const DeckNode* n = t.child_any({"max_timesteps", "max_Timesteps"})) {
    int v = n->as_int();
    if (v <= 0) n->fail("must be a positive integer");
    p.max_timesteps = v;
  }
  if (const DeckNode* n = t.child_any({"end_on_max_time_exactly", "end_at_max_time_exactly"}))
    p.end_exactly = n->as_bool();
  if (t.has_child("delt_init")) p.delt_init = positive(t, "delt_init");
  if (t.has_child("max_delt_increase")) p.max_delt_increase = positive(t, "max_delt_increase");
  return p;
}

std::set<std::string> ArchiverParameters::labels() const {
  std::set<std::string> out;
  for (const auto& s : saves) out.insert(s.label);
  return out;
}

std::string canonical_save_label(const std::string& label) {
  if (label.size() > 3 && label.compare(0, 2, "p.") == 0 && label.back() == '+') return label.substr(0, label.size() - 1);
  return label;
}

ArchiverParameters read_archiver_parameters(const DeckNode& a) {
  ArchiverParameters p;
  p.filebase = a.get_string("filebase", "");
  if (p.filebase.empty()) a.fail("missing <filebase> (the output directory)");
  const DeckNode* oi = a.child("outputInterval");
  const DeckNode* oti = a.child("outputTimestepInterval");
  if (oi && oti) oti->fail("give either <outputInterval> or <outputTimestepInterval>, not both");
  if (oi) {
    double v = oi->as_double();
    if (!(v > 0)) oi->fail("must be positive");
    p.output_interval = v;
  }
  if (oti) {
    int v = oti->as_int();
    if (v <= 0) oti->fail("must be a positive integer");
    p.output_timestep_interval = v;
  }
  for (const DeckNode* s : a.children_named("save")) {
    SaveRequest r;
    r.label = canonical_save_label(s->require_attribute("label"));
    r.material = s->attribute("material");
    p.saves.push_back(r);
  }
  if (const DeckNode* c = a.child("checkpoint")) {
    p.checkpoint = true;
    p.checkpoint_cycle = 2;
    if (auto cyc = c->attribute("cycle")) {
      auto v = parse_integer(*cyc);
      if (!v || *v <= 0) c->fail("checkpoint cycle must be a positive integer, found '" + *cyc + "'");
      p.checkpoint_cycle = static_cast<int>(*v);
    }
    auto iv = c->attribute("interval");
    auto tiv = c->attribute("timestepInterval");
    if (c->attribute("walltimeInterval") || c->attribute("walltimeStart"))
      c->missing_feature("wall-clock checkpoints (walltimeInterval): they make restarts depend on machine speed");
    if (iv && tiv) c->fail("give either interval or timestepInterval, not both");
    if (!iv && !tiv) c->fail("checkpoint needs interval or timestepInterval");
    if (iv) {
      auto v = parse_double(*iv);
      if (!v || *v <= 0) c->fail("checkpoint interval must be a positive number, found '" + *iv + "'");
      p.checkpoint_interval = *v;
    }
    if (tiv) {
      auto v = parse_integer(*tiv);
      if (!v || *v <= 0) c->fail("timestepInterval must be a positive integer, found '" + *tiv + "'");
      p.checkpoint_timestep_interval = static_cast<int>(*v);
    }
  }
  return p;
}

}  // namespace tephra
