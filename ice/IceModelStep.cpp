// The model phases of the ICE step (ice/models/IceModel.h): the sources of
// mass, momentum, energy and specific volume, the volume fractions they
// change, and the advection of model scalars. Uintah's ICE.cc order:
// computeModelSources -> updateVolumeFraction -> computeDelPressAndUpdatePressCC
// (delP_MassX) -> computeLagrangianValues (+ sources) -> computeLagrangianSpecificVolume
// (+ modelVol_src) -> advection (transported variables with the mass fluxes).
#include <cmath>
#include <sstream>

#include "core/base/Errors.h"
#include "core/grid/Loop.h"
#include "ice/IceAdvection.h"
#include "ice/IceBoundary.h"
#include "ice/IceComponent.h"

namespace tephra {

void IceComponent::allocate_model_storage() {
  if (setup_.models.empty()) return;
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  model_src_ = std::make_unique<IceModelSources>();
  model_src_->mass.assign(nm, CellScalars(g, 0));
  model_src_->energy.assign(nm, CellScalars(g, 0));
  model_src_->sp_vol.assign(nm, CellScalars(g, 0));
  model_src_->momentum.assign(nm, CellVectors(g, 0));
  delP_MassX_ = CellScalars(g, 2);
  delP_MassX_.fill(0.0);
  scalar_L_ = CellScalars(g, 2);
  for (const IceModelP& m : setup_.models) m->initialize(g, mats_);
}

// computeModelSources, then updateVolumeFraction (all cells, extra cells too):
//   V_tot = sum_m M_m v_m,  theta_m = max((theta_m V_tot + S_v,m)/V_tot, 1e-100),
// and the mass-exchange pressure term of eq. 26.2 (Uintah's term1),
//   delP_MassX sum_m theta_m kappa_m = sum_m S_M,m v_m / V,
// whose division by sum theta kappa happens with delP_Dilatate.
void IceComponent::compute_model_sources(double dt, int step) {
  const Grid& g = setup_.grid;
  const std::size_t nm = mats_.size();
  const double V = g.cell_volume();
  IceModelSources& s = *model_src_;
  for (std::size_t m = 0; m < nm; ++m) {
    s.mass[m].fill(0.0);
    s.energy[m].fill(0.0);
    s.sp_vol[m].fill(0.0);
    s.momentum[m].fill(Vec3::Zero());
    const IceSpecificHeat* cv_model = setup_.materials[m].cv_model.get();
    const double cv_const = setup_.materials[m].cv;
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
        cv_CC_[m][pi](i, j, k) = cv_model ? cv_model->cv(mats_[m].temp_CC[pi](i, j, k)) : cv_const;
      });
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi) fill_cell_gas_cv(m, pi);
  }
  const IceModelInput in{g, setup_.materials, mats_, cv_CC_, press_equil_CC_, time_, dt, step};
  for (const IceModelP& model : setup_.models) model->compute_sources(in, s);
  // Uintah's bulletProofing_ModelSources: a NaN or Inf stops the run.
  for (std::size_t m = 0; m < nm; ++m)
    for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
      for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
        if (std::isfinite(s.mass[m][pi](i, j, k)) && std::isfinite(s.energy[m][pi](i, j, k)) &&
            std::isfinite(s.sp_vol[m][pi](i, j, k)) && s.momentum[m][pi](i, j, k).allFinite())
          return;
        std::ostringstream os;
        os << "ICE model sources at step " << step << ": material " << m << " cell (" << i << "," << j << "," << k
           << ") has a NaN or Inf source";
        throw NumericalFailure(os.str());
      });
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
    for_each_cell(g.patches[pi].cells_with_extra(), [&](int i, int j, int k) {
      double total = 0, term1 = 0;
      for (std::size_t m = 0; m < nm; ++m) {
        const double v = mats_[m].sp_vol_CC[pi](i, j, k);
        total += mats_[m].rho_CC[pi](i, j, k) * V * v;
        term1 += s.mass[m][pi](i, j, k) * v / V;
      }
      for (std::size_t m = 0; m < nm; ++m) {
        double& theta = mats_[m].vol_frac_CC[pi](i, j, k);
        theta = std::max((theta * total + s.sp_vol[m][pi](i, j, k)) / total, 1e-100);
      }
      delP_MassX_[pi](i, j, k) = term1;
    });
  }
  for (IceMaterialFields& f : mats_) halo_->exchange(f.vol_frac_CC);
}

// A model scalar q of material m after advection (Uintah's
// computeLagrangian_Transported_Vars + advectAndAdvanceInTime):
//   q_L = q + src, zero-gradient extra cells,
//   q_new = (M_L q_L + sum of the face fluxes of q_L carried by the mass fluxes)/M_new.
// Called with flux_ holding material m's mass fluxes and mass_new_ its new mass.
void IceComponent::advect_model_scalars(std::size_t m, double dt) {
  const Grid& g = setup_.grid;
  const IceFaceBc zero_gradient{BCKind::Neumann, 0.0, Vec3::Zero()};
  for (const IceModelP& model : setup_.models)
    for (const TransportedScalar& ts : model->transported()) {
      if (ts.material != m) continue;
      CellScalars& q = *ts.q;
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
        const Patch& p = g.patches[pi];
        for_each_cell(p.cells(), [&](int i, int j, int k) {
          scalar_L_[pi](i, j, k) = q[pi](i, j, k) + (ts.src ? (*ts.src)[pi](i, j, k) : 0.0);
        });
        for (int face = 0; face < 6; ++face)
          apply_scalar_bc(g, p, static_cast<GridFace>(face), zero_gradient, scalar_L_[pi]);
      }
      halo_->exchange(scalar_L_);
      specific_fluxes(g, setup_.advection, scalar_L_, mats_[m].vel_FCME, flux_, dt, flux2_);
      flux_divergence(g, flux2_, dq_, radial());
      for (std::size_t pi = 0; pi < g.patches.size(); ++pi) {
        const Patch& p = g.patches[pi];
        for_each_cell(p.cells(), [&](int i, int j, int k) {
          q[pi](i, j, k) = (mass_L_[m][pi](i, j, k) * scalar_L_[pi](i, j, k) + dq_[pi](i, j, k)) / mass_new_[pi](i, j, k);
        });
        for (int face = 0; face < 6; ++face) apply_scalar_bc(g, p, static_cast<GridFace>(face), zero_gradient, q[pi]);
      }
      halo_->exchange(q);
    }
}

}  // namespace tephra
