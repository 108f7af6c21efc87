// The Pressure BC (with its hydrostatic adjustment) and the LODI boundary
// conditions in the ICE step (ice/Lodi.h), at the places
// Uintah's ICE sets them: the equilibration pressure and the updated
// pressure (amplitudes from rho_CC, vel_CC of the step's start, the pressure
// and the sound speed), the Lagrangian velocity and temperature after the
// exchange (Uintah's CC_Exchange), and the advected state (rho, vel, temp).
// Only the <LODI> material is touched (Uintah's rule); its other labels keep
// the BCs applied before these calls.
#include "core/grid/Loop.h"
#include "ice/IceBoundary.h"
#include "ice/IceComponent.h"

namespace tephra {

void IceComponent::apply_pressure_bc(std::size_t pi, CellScalars& press) {
  const Grid& g = setup_.grid;
  std::vector<const GridArray<double>*> rho;
  for (const IceMaterialFields& f : mats_) rho.push_back(&f.rho_CC[pi]);
  for (int face = 0; face < 6; ++face) {
    const GridFace gf = static_cast<GridFace>(face);
    const IceFaceBc& bc = setup_.bcs[0][face][kBcPressure];
    apply_scalar_bc(g, g.patches[pi], gf, bc, press[pi]);
    apply_hydrostatic_pressure_bc(g, g.patches[pi], gf, bc, setup_.gravity, rho, press[pi]);
  }
}

void IceComponent::lodi_pressure_bc(std::size_t pi, CellScalars& press) {
  const Grid& g = setup_.grid;
  const std::size_t L = static_cast<std::size_t>(setup_.lodi.material);
  const IceMaterialFields& f = mats_[L];
  const LodiState in{&f.rho_CC[pi], &press[pi], &f.vel_CC[pi], &f.speedSound_CC[pi], setup_.materials[L].gamma};
  for (int face = 0; face < 6; ++face)
    if (setup_.bcs[0][face][kBcPressure].kind == BCKind::LODI)
      apply_lodi_face(g, g.patches[pi], static_cast<GridFace>(face), setup_.lodi, setup_.gravity, in,
                      LodiTargets{nullptr, &press[pi], nullptr, nullptr});
}

void IceComponent::lodi_lagrangian_bc(std::size_t m, std::size_t pi) {
  if (static_cast<int>(m) != setup_.lodi.material) return;
  const Grid& g = setup_.grid;
  const IceMaterialFields& f = mats_[m];
  const LodiState in{&f.rho_CC[pi], &press_CC_[pi], &vel_L_[m][pi], &f.speedSound_CC[pi], setup_.materials[m].gamma};
  for (int face = 0; face < 6; ++face) {
    const auto& bc = setup_.bcs[m][face];
    LodiTargets out;
    if (bc[kBcVelocity].kind == BCKind::LODI) out.vel = &vel_L_[m][pi];
    if (bc[kBcTemperature].kind == BCKind::LODI) out.temp = &temp_L_[m][pi];
    if (out.vel || out.temp) apply_lodi_face(g, g.patches[pi], static_cast<GridFace>(face), setup_.lodi, setup_.gravity, in, out);
  }
}

void IceComponent::lodi_state_bc(std::size_t m, std::size_t pi) {
  if (static_cast<int>(m) != setup_.lodi.material) return;
  const Grid& g = setup_.grid;
  IceMaterialFields& f = mats_[m];
  const LodiState in{&f.rho_CC[pi], &press_CC_[pi], &f.vel_CC[pi], &f.speedSound_CC[pi], setup_.materials[m].gamma};
  for (int face = 0; face < 6; ++face) {
    const auto& bc = setup_.bcs[m][face];
    LodiTargets out;
    if (bc[kBcDensity].kind == BCKind::LODI) out.rho = &f.rho_CC[pi];
    if (bc[kBcVelocity].kind == BCKind::LODI) out.vel = &f.vel_CC[pi];
    if (bc[kBcTemperature].kind == BCKind::LODI) out.temp = &f.temp_CC[pi];
    if (!(out.rho || out.vel || out.temp)) continue;
    const GridFace gf = static_cast<GridFace>(face);
    apply_lodi_face(g, g.patches[pi], gf, setup_.lodi, setup_.gravity, in, out);
    // computeFromDensity reads the new extra-cell density.
    if (out.rho && bc[kBcSpecificVol].kind == BCKind::ComputeFromDensity)
      for_each_boundary_cell(g, g.patches[pi], gf, [&](const IntVec3& e, const IntVec3&) {
        f.sp_vol_CC[pi](e) = f.vol_frac_CC[pi](e) / f.rho_CC[pi](e);
      });
  }
}

}  // namespace tephra
