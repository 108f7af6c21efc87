#pragma once
// Helpers shared by the ICE source models: reading a model's parameters from
// the deck (with every child checked), naming materials, and moving reactant
// into product in one cell.
#include <limits>
#include <set>
#include <string>

#include "core/deck/DeckNode.h"
#include "ice/IceSetup.h"
#include "ice/models/IceModel.h"

namespace tephra {

// The parameters of one model: the children of `block`. Every child read is
// recorded; finish() rejects the others (DeckError naming the element), so a
// misspelt parameter never falls back to a default silently.
class ModelParams {
 public:
  ModelParams(const DeckNode& block, std::string what) : block_(block), what_(std::move(what)) {}
  const DeckNode& node() const { return block_; }
  double number(const char* name) {
    used_.insert(name);
    return block_.get_double(name);
  }
  double positive(const char* name) {
    used_.insert(name);
    const double v = block_.get_double(name);
    if (!(v > 0)) block_.require_child(name).fail(what_ + " <" + name + "> must be > 0");
    return v;
  }
  double number(const char* name, double fallback) {
    used_.insert(name);
    return block_.get_double(name, fallback);
  }
  bool flag(const char* name, bool fallback) {
    used_.insert(name);
    return block_.get_bool(name, fallback);
  }
  Vec3 vec3(const char* name) {
    used_.insert(name);
    return block_.get_vec3(name);
  }
  const DeckNode& child(const char* name) {
    used_.insert(name);
    return block_.require_child(name);
  }
  void accept(const char* name) { used_.insert(name); }  // read elsewhere, or no effect (documented)
  // Material named by <name> (its name attribute or its index in the deck).
  std::size_t material(const char* name, const IceSetup& setup);
  void finish() const {
    for (const DeckNode& c : block_.children)
      if (!used_.count(c.name)) c.fail(what_ + " has no parameter <" + c.name + ">");
  }

 private:
  const DeckNode& block_;
  std::string what_;
  std::set<std::string> used_;
};

// The block that holds a model's parameters: the <Type> child of <Model>
// when present (Uintah's layout, e.g. <Model type="JWLpp"><JWLpp>...), else
// <Model> itself (the stock Vaango decks write JWLpp parameters directly).
const DeckNode& model_block(const DeckNode& model, const char* block_name);

// Reactant m0 -> product m1 in one cell (Uintah's HEChem models): a mass dm
// leaves m0 with its velocity u, internal energy cv T per unit mass and
// specific volume v, and joins m1 together with the heat of reaction E0 dm.
inline void convert_mass(IceModelSources& s, std::size_t pi, const IntVec3& c, std::size_t m0, std::size_t m1,
                         double dm, const Vec3& u, double cvT, double v, double E0) {
  s.mass[m0][pi](c) -= dm;
  s.mass[m1][pi](c) += dm;
  s.momentum[m0][pi](c) -= dm * u;
  s.momentum[m1][pi](c) += dm * u;
  s.energy[m0][pi](c) -= dm * cvT;
  s.energy[m1][pi](c) += dm * cvT + dm * E0;
  s.sp_vol[m0][pi](c) -= dm * v;
  s.sp_vol[m1][pi](c) += dm * v;
}

// Forward-Euler diffusion of a cell scalar q (PassiveScalar, SimpleRxn):
// the source over one step in cell (i, j, k) with the 7-point Laplacian,
//   sum_d w_d (q_{+d} - 2 q + q_{-d}),   w_d = dt D / dx_d^2,
// so that where rho is uniform and the gas at rest q_t = D lap q. Stable for
// dt <= 1 / (2 D sum_d 1/dx_d^2) (infinity when D = 0).
inline double scalar_laplacian_step(const GridArray<double>& q, const Vec3& w, int i, int j, int k) {
  const double c = q(i, j, k);
  return w[0] * (q(i + 1, j, k) - 2 * c + q(i - 1, j, k)) + w[1] * (q(i, j + 1, k) - 2 * c + q(i, j - 1, k)) +
         w[2] * (q(i, j, k + 1) - 2 * c + q(i, j, k - 1));
}
inline double scalar_diffusion_stable_timestep(double D, const Vec3& dx) {
  if (D <= 0) return std::numeric_limits<double>::infinity();
  return 0.5 / (D * (1 / (dx[0] * dx[0]) + 1 / (dx[1] * dx[1]) + 1 / (dx[2] * dx[2])));
}

// Factories (ice/models/*.cpp).
IceModelP make_light_time(const DeckNode& model, const IceSetup& setup);
IceModelP make_jwlpp(const DeckNode& model, const IceSetup& setup);
IceModelP make_zero_order(const DeckNode& model, const IceSetup& setup);
IceModelP make_ignition_growth(const DeckNode& model, const IceSetup& setup);
IceModelP make_add_heat(const DeckNode& add_heat, const IceSetup& setup);
IceModelP make_passive_scalar(const DeckNode& model, const IceSetup& setup);
IceModelP make_simple_rxn(const DeckNode& model, const IceSetup& setup);
IceModelP make_mass_mom_eng_src(const DeckNode& model, const IceSetup& setup);

}  // namespace tephra
