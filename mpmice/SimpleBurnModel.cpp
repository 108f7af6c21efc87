// <Model type="Simple_Burn"> in MPMICE (mpmice/SolidBurn.h; the law and the
// surface functions in mpmice/SimpleBurn.h):
//   dm = dt A BurnCoeff (p_equil/refPressure)^0.778  where T > ThresholdTemp
//   and p_equil > ThresholdPressure, at most the solid's cell mass.
#include <string>

#include "core/deck/DeckNode.h"
#include "ice/IceSetup.h"
#include "ice/models/ModelSupport.h"
#include "mpmice/BurnModels.h"
#include "mpmice/SimpleBurn.h"
#include "mpmice/SolidBurn.h"

namespace tephra {

namespace {

class SimpleBurnModel final : public SolidBurnModel {
 public:
  SimpleBurnModel(const SimpleBurnParams& prm, std::size_t reactant, std::size_t product)
      : SolidBurnModel("Simple_Burn", "SimpleBurn", reactant, product, prm.enthalpy, prm.threshold_temperature),
        prm_(prm) {}

 protected:
  double burn_mass(const BurnCell& c) override {
    return simple_burn_mass(prm_, c.in->dt, c.area, c.pressure, c.temperature, c.solid_mass);
  }

 private:
  SimpleBurnParams prm_;
};

IceModelP make_simple_burn(const DeckNode& model, const IceSetup& setup) {
  ModelParams mp(model_block(model, "Simple_Burn"), "Simple_Burn");
  const std::size_t r = mp.material("fromMaterial", setup), p = mp.material("toMaterial", setup);
  check_reactant_product(mp, setup, r, p, "Simple_Burn");
  SimpleBurnParams prm;
  prm.threshold_temperature = mp.number("ThresholdTemp");
  prm.threshold_pressure = mp.number("ThresholdPressure");
  prm.enthalpy = mp.number("Enthalpy");
  prm.burn_coeff = mp.number("BurnCoeff");
  prm.ref_pressure = mp.positive("refPressure");
  mp.finish();
  return std::make_shared<SimpleBurnModel>(prm, r, p);
}

}  // namespace

void check_reactant_product(const ModelParams& mp, const IceSetup& setup, std::size_t r, std::size_t p,
                            const char* what) {
  if (!setup.materials[r].lagrangian)
    mp.node().require_child("fromMaterial").fail(std::string(what) + ": <fromMaterial> must be an MPM material");
  if (setup.materials[p].lagrangian)
    mp.node().require_child("toMaterial").fail(std::string(what) + ": <toMaterial> must be an ICE material");
}

IceModelP make_steady_burn(const DeckNode& model, const IceSetup& setup);    // SteadyBurnModel.cpp
IceModelP make_unsteady_burn(const DeckNode& model, const IceSetup& setup);  // UnsteadyBurnModel.cpp
IceModelP make_ddt1(const DeckNode& model, const IceSetup& setup);           // Ddt1Model.cpp
IceModelP make_ddt0(const DeckNode& model, const IceSetup& setup);           // Ddt0Model.cpp
IceModelP make_test_model(const DeckNode& model, const IceSetup& setup);     // TestMassModel.cpp
IceModelP make_solid_reaction_model(const DeckNode& model, const IceSetup& setup);  // SolidReactionModel.cpp
IceModelP make_meso_burn(const DeckNode& model, const IceSetup& setup);      // MesoBurnModel.cpp

IceModelFactories mpmice_burn_model_factories() {
  IceModelFactories f;
  f["Simple_Burn"] = make_simple_burn;
  f["Steady_Burn"] = make_steady_burn;
  f["Unsteady_Burn"] = make_unsteady_burn;
  f["DDT1"] = make_ddt1;
  f["DDT0"] = make_ddt0;
  f["Test"] = make_test_model;
  f["SolidReactionModel"] = make_solid_reaction_model;
  f["MesoBurn"] = make_meso_burn;
  return f;
}

}  // namespace tephra
