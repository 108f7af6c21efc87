#pragma once
// Manufactured solutions of explicit MPM (<MPM><run_MMS_problem>, Vaango's
// MPM/MMS/MMS.cc): a prescribed motion x = X + u(X, t) of a cnh_mms solid
// (models/solid/CnhMms.h) and the body force per unit mass that makes it an
// exact solution of  rho0 d2u/dt2 = Div P + rho0 b:
//   b(X, t) = d2u/dt2 - (1/rho0) Div P(F(X, t)),   F = I + Grad u.
// The run starts from u(X, 0), du/dt(X, 0), F(X, 0); every step applies
// f_ext,p = m_p b(X_p, t_n) with X_p = x_p - u_p (Vaango: p.externalforce).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/base/Types.h"
#include "models/solid/CnhMms.h"

namespace tephra {

struct Particles;

class ManufacturedSolution {
 public:
  virtual ~ManufacturedSolution() = default;
  virtual std::string name() const = 0;  // Vaango's run_MMS_problem value
  virtual Vec3 displacement(const Vec3& X, double t) const = 0;  // u
  virtual Vec3 velocity(const Vec3& X, double t) const = 0;      // du/dt
  virtual Mat3 deformation_gradient(const Vec3& X, double t) const = 0;  // I + Grad u
  virtual Vec3 body_force(const Vec3& X, double t) const = 0;    // b [m/s^2]
};

// AxisAligned (Vaango initAxisAligned / extForceAxisAligned), on the unit cube:
//   u_i = A sin(pi X_i) sin(c pi t + phi_i),  A = 0.05, phi = (0, 2 pi/3, 4 pi/3),
//   c = sqrt(E / rho0), E = 9 K mu / (3 K + mu)  (= 1e4 with the AA.ups moduli);
//   F = diag(1 + A pi cos(pi X_i) sin(c pi t + phi_i)),
//   b_i = pi^2 u_i [ mu/rho0 - c^2 - (lambda (ln J - 1) - mu) / (rho0 F_ii^2) ].
// (b_i from Div P for diagonal F: dP_ii/dX_i = F_ii' [mu - (lambda (ln J - 1) - mu)/F_ii^2],
// F_ii' = -pi^2 u_i, and d2u_i/dt2 = -(c pi)^2 u_i.) Vaango hard-codes K =
// 8333.33, mu = 3846.15, rho0 = 1; Tephra takes K, mu, rho0 from the deck so
// that the body force matches the stress the run computes.
// `amplitude` is A; decks get Vaango's 0.05 (make_mms). Other values are for
// the amplitude split of docs/mpm-convergence.md (session 24): the error part
// linear in A (small strain) against the part from the large strain.
std::unique_ptr<ManufacturedSolution> make_axis_aligned_mms(const CnhMmsParams& model, double rho0,
                                                            double amplitude = 0.05);

// GeneralizedVortex (Vaango initGeneralizedVortex / extForceGeneralizedVortex;
// Kamojjala et al.), an isochoric rotation of each circle R = |(X, Y)| about z:
//   x = Q(alpha) X,  alpha = A sin(c pi t) h(R),  h(R) = 1 - 32 (R-1)^2 + 256 (R-1)^4
//                                                      = ((4R-3)(4R-5))^2,
//   A = 1, c = sqrt(E/rho0) with Vaango's E = 1000 (here E = 9 K mu/(3K + mu)).
// h = 0 and h' = 0 at R = 3/4 and 5/4 (the ring's faces are traction free).
// b in polar components at the current angle beta = theta + alpha:
//   b_r = -R (A c pi cos(c pi t))^2 h + (mu/rho0) R (A sin(c pi t) h')^2 ... (see .cpp)
std::unique_ptr<ManufacturedSolution> make_generalized_vortex_mms(const CnhMmsParams& model, double rho0);

// ExpandingRing (Vaango initExpandingRing / extForceExpandingRing): a ring
// 0.4 <= R <= 0.6 breathing radially, u = A sin(omega t) g(R) (X, Y, 0),
// A = 0.1, omega = C pi / (2 rb), g quadratic with (R g)' = 0 at both faces
// (formulas and the body force in ExpandingRing.cpp).
std::unique_ptr<ManufacturedSolution> make_expanding_ring_mms(const CnhMmsParams& model, double rho0);

// Names Vaango accepts for run_MMS_problem, and the implemented ones.
const std::vector<std::string>& vaango_mms_names();
const std::vector<std::string>& implemented_mms_names();
// Creates the named solution; nullptr when not implemented.
std::unique_ptr<ManufacturedSolution> make_mms(const std::string& name, const CnhMmsParams& model, double rho0);

// Sets the initial state of particles seeded at reference positions X = p.x:
// x = X + u(X,0), u_p = u(X,0), v = du/dt(X,0), F = F(X,0), V = det F V0.
void initialize_mms_particles(const ManufacturedSolution& mms, Particles& p);
// v_p = du/dt(X_p, t), X_p = x_p - u_p: the leapfrog start velocity
// v(-dt/2) of the first step (see MpmComponent::advance).
void set_mms_velocity(const ManufacturedSolution& mms, double t, Particles& p);
// f_ext,p = m_p b(X_p, t), X_p = x_p - u_p.
void apply_mms_body_force(const ManufacturedSolution& mms, double t, Particles& p);
// L2 norm of the displacement error over the particles, weighted by the
// reference volume: sqrt( sum V0_p |u_p - u(X_p, t)|^2 / sum V0_p ).
double mms_displacement_error_l2(const ManufacturedSolution& mms, const Particles& p, double t);
// Its two sums {sum V0_p |u_p - u(X_p, t)|^2, sum V0_p} over the particles of p
// (on MPI ranks each rank's, added over the ranks before the root is taken).
std::array<double, 2> mms_displacement_error_sums(const ManufacturedSolution& mms, const Particles& p, double t);

}  // namespace tephra
