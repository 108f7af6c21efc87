#include "models/solid/HypoElasticMms.h"

#include "models/ModelParameters.h"

namespace tephra {

ConstitutiveModelP HypoElasticMms::create(const ModelParameters& params) {
  HypoElasticParams p;
  p.G = params.get_double("G");
  p.K = params.get_double("K");
  if (!(p.G > 0.0)) params.fail("G", "G (shear modulus) must be > 0");
  if (!(p.K > 0.0)) params.fail("K", "K (bulk modulus) must be > 0");
  if (params.get_double("alpha", 0.0) != 0.0)
    params.missing_feature("alpha", "hypo_elastic_mms thermal stress (alpha != 0)");
  return std::make_shared<HypoElasticMms>(p);
}

}  // namespace tephra
