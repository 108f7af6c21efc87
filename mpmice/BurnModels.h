#pragma once
// The MPMICE burn models of <Models> (mpmice/SolidBurn.h): Simple_Burn,
// Steady_Burn, Unsteady_Burn, DDT1, DDT0, Test, SolidReactionModel.
// read_ice_setup takes them through these factories; the MpmIceComponent
// attaches itself to them (SolidBurnModel::attach).
#include <cstddef>

#include "ice/models/IceModel.h"
#include "mpmice/SteadyBurn.h"

namespace tephra {

class ModelParams;
struct IceSetup;

IceModelFactories mpmice_burn_model_factories();

// Test's converted fraction per step, min(rate dt, 1) (mpmice/TestMassModel.cpp).
double test_model_fraction(double rate, double dt);

// Deck check every burn model makes: <fromMaterial> (index r) must be an MPM
// material, <toMaterial> (index p) an ICE one; `what` names the model.
void check_reactant_product(const ModelParams& mp, const IceSetup& setup, std::size_t r, std::size_t p,
                            const char* what);

struct WsbIgnition;

// The WSB constants every WSB burn model reads (<IdealGasConst> ...
// <MoleWeightGasPh>; SteadyBurnModel.cpp) and the ignition parameters
// (<BoundaryParticles>, <IgnitionTemp>; mpmice/WsbSurfaceCell.h).
WsbParams read_wsb_params(ModelParams& mp);
WsbIgnition read_wsb_ignition(ModelParams& mp);

}  // namespace tephra
