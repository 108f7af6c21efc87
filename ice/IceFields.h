#pragma once
// Grid storage of the ICE step: per material cell-centred state (_CC) and
// normal face velocities (_FC), one field per patch (core/grid/Fields.h).
#include <array>

#include "core/grid/Fields.h"

namespace tephra {

using CellScalars = PatchFields<CellField<double>>;
using CellVectors = PatchFields<CellField<Vec3>>;

// A value on the x-, y- and z-faces (e.g. the normal velocity: uvel_FC,
// vvel_FC, wvel_FC in Uintah's names).
template <class T>
struct FaceData {
  PatchFields<FaceField<T, 0>> x;
  PatchFields<FaceField<T, 1>> y;
  PatchFields<FaceField<T, 2>> z;

  FaceData() = default;
  FaceData(const Grid& g, int ghosts) : x(g, ghosts), y(g, ghosts), z(g, ghosts) {}
  GridArray<T>& at(int dir, std::size_t patch) {
    if (dir == 0) return x[patch];
    if (dir == 1) return y[patch];
    return z[patch];
  }
  const GridArray<T>& at(int dir, std::size_t patch) const { return const_cast<FaceData*>(this)->at(dir, patch); }
};
using FaceScalars = FaceData<double>;

// One ICE material's fields. The state carried between steps is rho_CC,
// vel_CC, temp_CC and sp_vol_CC (with their extra cells); the rest are
// results of the step kept for output, the time step and restart.
struct IceMaterialFields {
  CellScalars rho_CC;        // bulk density M/V = theta * rho_micro
  CellVectors vel_CC;
  CellScalars temp_CC;
  CellScalars sp_vol_CC;     // 1/rho_micro
  CellScalars rho_micro_CC;  // equilibration result
  CellScalars vol_frac_CC;   // theta
  CellScalars speedSound_CC;
  FaceScalars vel_FC;        // face velocities before exchange (eq. 26.1)
  FaceScalars vel_FCME;      // after the face momentum exchange
  CellVectors mom_L_CC;      // Lagrangian momentum before exchange, M u + dt(...) (eq. 26.8; output label)
  CellScalars int_eng_L_CC;  // Lagrangian internal energy before exchange (eq. 26.10; output label)
  CellVectors mom_L_ME_CC;   // Lagrangian momentum after exchange (output label)
  CellScalars eng_L_ME_CC;   // Lagrangian internal energy after exchange
  CellVectors mom_source_CC; // dt (-V theta grad p* + M g + V div(theta tau)) of the step (eq. 26.5)

  IceMaterialFields() = default;
  IceMaterialFields(const Grid& g, int ghosts)
      : rho_CC(g, ghosts), vel_CC(g, ghosts), temp_CC(g, ghosts), sp_vol_CC(g, ghosts), rho_micro_CC(g, ghosts),
        vol_frac_CC(g, ghosts), speedSound_CC(g, ghosts), vel_FC(g, 0), vel_FCME(g, 0), mom_L_CC(g, 0),
        int_eng_L_CC(g, 0), mom_L_ME_CC(g, ghosts),
        eng_L_ME_CC(g, ghosts), mom_source_CC(g, ghosts) {}
};

}  // namespace tephra
