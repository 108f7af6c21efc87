#pragma once
// LODI characteristic boundary conditions (var="LODI" on a face; the
// <BoundaryConditions><LODI> block), after Uintah's ICE LODI2 and its source,
// Sutherland & Kennedy, "Improved boundary conditions for viscous, reacting,
// compressible flows", J. Comput. Phys. 191 (2003) 502-524 (tables 4-7), and
// Poinsot & Lele, J. Comput. Phys. 101 (1992) 104-129 (the relaxation term).
//
// For the face normal n (axis d) and the inner cell next to it, the wave
// amplitudes of the locally one-dimensional inviscid equations are
//   L1 = (u - c)/2 (p_n - rho c u_n)     (acoustic wave travelling along -n)
//   L2 = u (rho_n - p_n/c^2)             (entropy wave)
//   L3 = u v_n,  L4 = u w_n              (vorticity waves; v, w tangential)
//   L5 = (u + c)/2 (p_n + rho c u_n)     (acoustic wave along +n)
// with u the normal velocity and q_n one-sided first-order differences of the
// inner cell and its inner neighbour (Uintah's computeLi). The amplitudes of
// the waves entering the domain are replaced:
//   subsonic outflow: the incoming acoustic amplitude (L1 on a high face, L5
//     on a low face) = K (p - p_inf)/(2 L_d) + s, K = sigma c (1 - Ma_max^2),
//     L_d the domain length along d, Ma_max the largest Mach number on the
//     face (a partially non-reflecting outflow relaxed toward p_inf);
//   subsonic inflow: L2 = L3 = L4 = s and the incoming acoustic amplitude = s;
//   supersonic inflow: every L = s; supersonic outflow: unchanged;
// s are the body-force sources (table 4 with the normal gravity only:
// s1 = -rho c g_n/2, s5 = +rho c g_n/2, s2 = s3 = s4 = 0). Every L is then
// multiplied by Li_scale. The normal gradients follow from the amplitudes
// (table 6) and the extra cell gets q_extra = q_inner + (+-dx) q_n:
//   p_n   = L5/(u + c) + L1/(u - c)
//   rho_n = L2/u + (L5/(u + c) + L1/(u - c))/c^2
//   u_n   = (L5/(u + c) - L1/(u - c))/(rho c),  v_n = L3/u, w_n = L4/u
//   T_n   = T/(rho c^2) (-L2/u + (gamma - 1)(L5/(u + c) + L1/(u - c)))
// Without replacement these give back the one-sided differences: the
// condition only removes (relaxes) the incoming waves.
// Extra cells on the edges and corners of the face copy the value of the
// nearest extra cell on the face itself (Uintah copies an inner diagonal
// neighbour on edges and writes constants in corners).
#include "core/grid/BoundaryConditions.h"
#include "core/grid/Fields.h"
#include "core/grid/Grid.h"

namespace tephra {

struct LodiSettings {
  bool enabled = false;
  double press_infinity = 0;  // <press_infinity> [Pa]
  double sigma = 0.27;        // <sigma>, Uintah's default
  double li_scale = 1.0;      // <Li_scale>
  int material = 0;           // the ICE material whose state defines the waves
};

// The state the amplitudes are computed from (inner cells) and what the
// extra cells receive. Null targets are skipped. temp must hold the inner
// temperature when it is a target; gamma is the material's ratio of specific heats.
struct LodiState {
  const GridArray<double>* rho = nullptr;
  const GridArray<double>* press = nullptr;
  const GridArray<Vec3>* vel = nullptr;
  const GridArray<double>* speed_sound = nullptr;
  double gamma = 1.4;
};
struct LodiTargets {
  GridArray<double>* rho = nullptr;
  GridArray<double>* press = nullptr;
  GridArray<Vec3>* vel = nullptr;
  GridArray<double>* temp = nullptr;
};

// Sets the extra cells of patch p on domain face f (nothing if p does not
// touch f). The targets may alias the state arrays (the inner cells are
// read, the extra cells written).
void apply_lodi_face(const Grid& g, const Patch& p, GridFace f, const LodiSettings& s, const Vec3& gravity,
                     const LodiState& in, const LodiTargets& out);

}  // namespace tephra
