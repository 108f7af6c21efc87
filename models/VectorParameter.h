#pragma once
// A model parameter given as a 3-vector, "[x, y, z]" (the deck's vector form;
// brackets and commas optional, as Vaango's readers accept). One reader for
// every model (trans_iso_hyper's fibre direction, polar_orthotropic's axis,
// program_burn's starting point and plane normal).
#include <optional>
#include <string>

#include <Eigen/Core>

#include "models/ModelParameters.h"

namespace tephra {

// The vector, or std::nullopt when the parameter is absent (or empty);
// three finite numbers or a DeckError at the parameter (params.fail).
std::optional<Eigen::Vector3d> optional_vector_parameter(const ModelParameters& params, const std::string& name);
// The same, required: absent is a DeckError too.
Eigen::Vector3d vector_parameter(const ModelParameters& params, const std::string& name);

}  // namespace tephra
