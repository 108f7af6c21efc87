#pragma once
// Axisymmetric MPM (<MPM><axisymmetric>true), Vaango's convention: x = r
// (radius, r >= 0), y = z (axial), and the third grid direction stands for
// the hoop angle: one cell, whose two node planes share every weight. All
// extensive quantities are per radian:
//   V_p = A_p r_p (A_p = h_x h_y / (res_x res_y) the particle's area), m_p = rho V_p.
// GIMP and CPDI: mpm/shape/ShapeAxisymmetric.h (the same hoop convention).
// cpti: Uintah's axiCptiInterpolator is the axiCpdi parallelogram form (4
// corners, 1/8 per corner and hoop plane), so Tephra uses the CPDI entries;
// Vaango keeps its planar (non-axisymmetric) linear interpolator for cpti
// with <axisymmetric> (its MPMFlags sets no interpolator in that branch).
// 3rdorderBS, 4thorderBS (Vaango: "can't be used with axisymmetry", a setup
// error) and Tephra's cpgimp: the planar in-plane weights S_r(r) S_z(z) / 2
// per hoop plane with the hoop factor T = S / r_p (docs/mpm-convergence.md
// "Axisymmetric MPM" for their orders).
// Linear (axisymmetric) shape functions (Vaango's AxiLinearInterpolator):
//   S = N_x(r) N_y(z) / 2 on each of the two hoop planes,
//   grad S = (dN_x/dr N_y / 2, N_x dN_y/dz / 2, S / r_p),
// the third component carrying the hoop terms:
//   hoop rate      l_thth = sum_g v_r,g S_gp / r_p = v_r / r       (l_rth = l_thr = l_zth = l_thz = 0)
//   internal force f_r,g = - sum_p V_p (sigma_rr dS/dr + sigma_rz dS/dz + sigma_thth S / r_p)
//                  f_z,g = - sum_p V_p (sigma_zr dS/dr + sigma_zz dS/dz),   f_th,g = 0
// (the weak form of d sigma_rr/dr + d sigma_rz/dz + (sigma_rr - sigma_thth)/r = rho a_r
// with dV = r dr dz per radian). The F update is the ordinary one with this l
// (F_thth = r / R for the hoop stretch).
#include <vector>

#include "core/base/Types.h"
#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

// Turns freshly seeded particles (3-D volumes h_x h_y h_z / res) into
// per-radian ones: V = (V_3d / dz_p) r, m = rho V; dz_p = h_z / res_z.
void make_axisymmetric_particles(const Vec3& h, double density, Particles& p);

// Entries per particle: linear 8, gimp and 3rdorderBS 18 (3 x 3 in-plane
// nodes x 2 hoop planes), cpdi and cpti 32 (4 corners x 2 x 2 nodes x 2
// planes), 4thorderBS and cpgimp 32 (up to 4 x 4 x 2).
int axisymmetric_stencil_width(InterpolatorKind kind);

// The stencils of `kind` (linear above; gimp and cpdi: mpm/shape/ShapeAxisymmetric.h):
// grad = (dS/dr, dS/dz, T) with T the hoop factor (S / r_p for linear and cpdi,
// the volume average of N / r for gimp; ShapeAxis factors for the B-splines
// and cpgimp). Returns the first particle outside
// the grid (or with r <= 0, or a degenerate CPDI domain), or -1.
long compute_axisymmetric_stencils(const Particles& p, const NodeGrid& g, InterpolatorKind kind, Stencils& s);

// The volume V_full(i) = sum_p V_p S_gp of a node at r_i = origin_x + i h_r
// (i = 0 .. n_x - 1) surrounded by material, per radian and per hoop node
// plane: every axisymmetric interpolator puts S/2 on each of the two hoop
// planes (not folded), and the body integral of the in-plane weight is
// int N_i(r) r dr int N_j(z) dz = J(r_i) h_z with
//   J(r) = int_{max(0, r - h_r)}^{r + h_r} N(s) s ds = r h_r        (r >= h_r)
//        = r h_r / 2 + h_r^2 / 6 + (r h_r L - (h_r + r) L^2 / 2 + L^3 / 3) / h_r,  L = r  (0 <= r < h_r)
// (h_r^2 / 6 on the axis), so V_full(i) = J(|r_i|) h_z / 2 (extra nodes at r < 0:
// their mirror's). Exact for GIMP (S V_p = the domain integral of N); the
// linear hat's midpoint rule gives it to O(h^2). The node fill of the MUSL/USL
// choice is phi_g = V_g / V_full (mpm/UpdatedGridVelocity.h): the Cartesian
// V_g / (h_x h_y h_z) takes a full node at radius r for r / (2 h_z) of one.
std::vector<double> axisymmetric_full_node_volumes(const NodeGrid& g);

// f_int with the hoop term (overwrites nothing: adds into g.internal_force).
void axisymmetric_internal_force(const Particles& p, const Stencils& s, NodeGrid& g);

// l_p with the hoop rate l_thth = v_r / r.
void axisymmetric_velocity_gradients(const Stencils& s, const NodeGrid& g, std::vector<Mat3>& L);

}  // namespace tephra
