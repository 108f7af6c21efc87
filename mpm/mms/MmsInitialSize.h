#pragma once
// The particle size at t = 0 of a manufactured-solution run, as Vaango sets it.
//
// Vaango's initAxisAligned (MPM/MMS/MMS.cc) sets p.size = diag(size_dd F_dd(X, 0)),
// the deformed domain at t = 0; initGeneralizedVortex and initExpandingRing
// keep the seeded size. Vaango then keeps p.size fixed for every interpolator
// but cpdi/cpti, whose domain is F p.size (SerialMPM computeCurrentParticleSize;
// GIMPInterpolator reads l = p.size(d,d)/2 and ignores F). So a Vaango run of
// AA.ups with `gimp` uses the t = 0 deformed domain for the whole run.
#include "mpm/mms/ManufacturedSolution.h"

namespace tephra {

struct Particles;

// True for the solutions whose Vaango init sets the deformed size (AxisAligned).
bool mms_deformed_initial_size(const ManufacturedSolution& mms);

// p.size(d,d) *= F_dd(X, 0) with X = x - u (after initialize_mms_particles),
// off-diagonal terms 0. Call it only for interpolators whose domain is p.size
// itself (not cpdi, cpti, cpgimp: their domain F p.size already holds F(X, 0);
// Vaango's F(X,0) with the deformed p.size counts F(X, 0) twice there).
// Applied only if every deformed size is <= max_size (cell units; uGIMP's
// weights hold for l = size/2 <= 1/2, so max_size = 1 for gimp). Returns false,
// sizes unchanged, otherwise and when the solution keeps the seeded size.
bool set_mms_deformed_initial_size(const ManufacturedSolution& mms, Particles& p, double max_size);

}  // namespace tephra
