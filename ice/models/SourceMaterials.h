#pragma once
// Optional interface of an ICE model (ice/models/IceModel.h): the materials
// the model writes sources for (reactant and product, the heated or
// scalar-carrying material). MPMICE (mpmice/MpmIceDeck.cpp) admits an ICE
// model only when it has this interface and none of these materials is an MPM
// material: a source on an MPM material's cell copy would never reach the
// particles. (An interface of its own, so that IceModel.h does not change.)
#include <cstddef>
#include <vector>

namespace tephra {

class SourceMaterials {
 public:
  virtual ~SourceMaterials() = default;
  virtual std::vector<std::size_t> source_materials() const = 0;
};

}  // namespace tephra
