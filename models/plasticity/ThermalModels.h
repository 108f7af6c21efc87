#pragma once
// Shear-modulus (VT ch. 7), melting-temperature (ch. 13) and specific-heat
// (ch. 14) sub-models: scalar point functions of (ρ, T, p̄, T_m).
#include <memory>
#include <string>
#include <vector>

#include "models/plasticity/SubModelTable.h"

namespace tephra {

class ShearModulusModel {
 public:
  virtual ~ShearModulusModel() = default;
  virtual std::string type() const = 0;
  // μ at the state (uses density, density0, temperature, melt_temperature, pressure).
  virtual double shear_modulus(const PlasticState& s) const = 0;
};

class MeltingTemperatureModel {
 public:
  virtual ~MeltingTemperatureModel() = default;
  virtual std::string type() const = 0;
  virtual double melt_temperature(const PlasticState& s) const = 0;  // T_m [K]
};

class SpecificHeatModel {
 public:
  virtual ~SpecificHeatModel() = default;
  virtual std::string type() const = 0;
  virtual double specific_heat(const PlasticState& s) const = 0;  // C_p [J/(kg K)]
};

const std::vector<SubModelEntry<ShearModulusModel>>& shear_modulus_models();
const std::vector<SubModelEntry<MeltingTemperatureModel>>& melting_temperature_models();
const std::vector<SubModelEntry<SpecificHeatModel>>& specific_heat_models();

// nullptr for an unknown key.
std::unique_ptr<ShearModulusModel> create_shear_modulus_model(const std::string& key, const ModelParameters& p,
                                                              const SubModelContext& ctx = {});
std::unique_ptr<MeltingTemperatureModel> create_melting_temperature_model(const std::string& key,
                                                                          const ModelParameters& p,
                                                                          const SubModelContext& ctx = {});
std::unique_ptr<SpecificHeatModel> create_specific_heat_model(const std::string& key, const ModelParameters& p,
                                                              const SubModelContext& ctx = {});

}  // namespace tephra
