// <Model type="Test"> in MPMICE (Uintah's Models/TestModel.cc, read for the
// rule and the parameter names): from <startTime> on (default 0), every cell
// moves the fraction min(<rate> dt, 1) of its <fromMaterial> mass to
// <toMaterial>, with its momentum and c_v T energy and no heat release:
//   dm_c = min(rate dt, 1) M_r,c.
// Here the reactant is an MPM material: the mass is taken from the particles
// by the common burn machinery (mpmice/SolidBurn.h, ParticleBurn.cpp), so the
// particles lose exactly what the product gains; since the particles' share
// of a cell is its projected mass M_r,c, the solid's total mass follows
//   M(t_n) = M(t_0) prod_k (1 - rate dt_k)          (docs/mpmice.md).
// Sums (Uintah's labels): totalMassExchanged, totalIntEngExchanged.
// Not implemented (MissingFeature, exit 3): an ICE <fromMaterial> (Uintah
// allows ICE -> ICE), and <Model type="Test"> in a pure ICE deck.
#include <algorithm>

#include "core/deck/DeckNode.h"
#include "ice/IceSetup.h"
#include "ice/models/ModelSupport.h"
#include "mpmice/BurnModels.h"
#include "mpmice/SolidBurn.h"

namespace tephra {

double test_model_fraction(double rate, double dt) { return std::min(rate * dt, 1.0); }

namespace {

class TestMassModel final : public SolidBurnModel {
 public:
  TestMassModel(double rate, double start_time, std::size_t reactant, std::size_t product)
      : SolidBurnModel("Test", "Test", reactant, product, 0.0, 0.0), rate_(rate), start_(start_time) {}

  bool select_cell(const double /*wm*/[8], BurnCell& cell) const override {
    cell.surface = false;
    return cell.in->time >= start_ && cell.solid_mass > 0;
  }

  std::set<std::string> labels() const override { return {"totalMassExchanged", "totalIntEngExchanged"}; }
  std::vector<ModelField> fields() const override { return {}; }
  std::vector<ModelSum> patch_sums() const override {
    return {{"totalMassExchanged", &burn_sums(), 0, 1}, {"totalIntEngExchanged", &burn_sums(), 2, 1}};
  }

 protected:
  double burn_mass(const BurnCell& c) override { return test_model_fraction(rate_, c.in->dt) * c.solid_mass; }

 private:
  double rate_, start_;
};

}  // namespace

IceModelP make_test_model(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model_block(model, "Test"), "Test");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  if (!setup.materials[r].lagrangian)
    mp.node().require_child("fromMaterial").missing_feature("Model type 'Test' with an ICE <fromMaterial>");
  check_reactant_product(mp, setup, r, p, "Test");
  const double rate = mp.number("rate");
  if (!(rate >= 0)) mp.node().require_child("rate").fail("Test <rate> must be >= 0");
  const double start = mp.number("startTime", 0.0);
  mp.finish();
  return std::make_shared<TestMassModel>(rate, start, r, p);
}

}  // namespace tephra
