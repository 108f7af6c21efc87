#pragma once
// Creators of the EOS models other than the ideal gas (one .cpp per family:
// GasEos.cpp, ExplosiveProductEos.cpp, SolidEos.cpp, WaterEos.cpp). Each
// reads its parameters (Vaango's names, ups_spec/ice_spec.xml) and checks them.
#include "models/eos/EquationOfState.h"

namespace tephra {

EquationOfStateP make_hard_sphere_gas(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_tst(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_jwl(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_jwlc(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_murnaghan(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_birch_murnaghan(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_gruneisen(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_tillotson(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_thomsen_hartka_water(const ModelParameters& p, const EosMaterialConstants& c);
EquationOfStateP make_knauss_sea_water(const ModelParameters& p, const EosMaterialConstants& c);

// Parameter helpers for the creators.
double eos_positive(const ModelParameters& p, const char* name);
double eos_required(const ModelParameters& p, const char* name);

}  // namespace tephra
