#pragma once
// Chapman-Jouguet state of a barotropic JWLC product EOS (tests of detonations).
//   p(V) = A e^{-R1 V} + B e^{-R2 V} + C V^{-(1+om)},   V = rho0/rho.
// With a reactant that depends on density only, mass and momentum fix a
// steady detonation from (rho0, p0, u = 0) to the products at V:
//   mass: u = D (1 - V);  momentum (Rayleigh line): p - p0 = rho0 D^2 (1 - V).
// The CJ point is where the Rayleigh line touches p(V):
//   rho0 D^2 = -p'(V),  p(V) - p0 = -p'(V) (1 - V),
// one equation in V, solved by bisection on [0.3, 0.99]; D_CJ = sqrt(-p'(V)/rho0).
// (Used by tests/verification/test_ice_reactions.cpp and test_mpmice_jwlpp.cpp; the same derivation as
// tests/bench/jwlc_cj.py: ANFO JWLEOSANFO.xml gives V_CJ = 0.748,
// p_CJ = 10.17 GPa, D_CJ = 5899.3 m/s.)
namespace tephra::test {

struct JwlcProducts {
  double A, B, C, R1, R2, om, rho0;
  double p(double V) const;
  double dp_dV(double V) const;
};

struct CjState {
  double V, p, D;
};

// Throws std::runtime_error when [0.3, 0.99] does not bracket the CJ point.
CjState chapman_jouguet(const JwlcProducts& e, double p0);

}  // namespace tephra::test
