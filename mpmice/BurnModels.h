#pragma once
// The MPMICE burn models of <Models> (mpmice/SolidBurn.h): Simple_Burn,
// Steady_Burn. read_ice_setup takes them through these factories; the
// MpmIceComponent attaches itself to them (SolidBurnModel::attach).
#include "ice/models/IceModel.h"

namespace tephra {

IceModelFactories mpmice_burn_model_factories();

}  // namespace tephra
