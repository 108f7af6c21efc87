#pragma once
// Explicit heat conduction on the MPM grid and thermal contact between
// materials (Vaango: <MPM><do_explicit_heat_conduction>, default true, and
// <MaterialProperties><MPM><thermal_contact/>). The theory manual gives no
// equations for MPM conduction (inventory §1.5, "gap"); the discretisation is
// the Galerkin one of the heat equation rho c_v dT/dt = div(k grad T) with the
// particles as quadrature points and the lumped capacity, as Vaango's
// HeatConduction (computeInternalHeatRate, solveHeatEquations,
// integrateTemperatureRate) and STThermalContact compute it:
//
//   P2G       T_g = sum_p m_p T_p S_gp / m_g                                (mass weighted)
//   gradient  grad T_p = sum_g T_g grad S_gp
//   rate      (dT/dt)_g = -1/(c_v m_g) sum_p k V_p grad S_gp . grad T_p    (conduction)
//   contact   T_c = sum_m m_g^m c_v^m T_g^m / sum_m m_g^m c_v^m,  (dT/dt)_g^m += (T_c - T_g^m)/dt
//   G2P       T_p += dt (sum_g (dT/dt)_g S_gp + hdot_p)
//
// hdot_p is the particle's internal heating rate from the constitutive model
// (adiabatic plastic work, VT eq. 14.1 / 17.27) and the artificial-viscosity
// heating. With insulated faces the scheme conserves sum_p m_p c_v T_p to
// round-off: sum_g grad S_gp = 0 (partition of unity) makes the conduction
// rates sum to zero over the nodes weighted by m_g c_v, the contact rates
// sum to zero by the definition of T_c, and G2P hands the nodes' energy
// change back through sum_p m_p S_gp = m_g.
#include <vector>

#include "mpm/NodeGrid.h"
#include "mpm/Particles.h"
#include "mpm/shape/Interpolator.h"

namespace tephra {

// The node temperature fields of one material, allocated only when the run
// conducts heat (or exchanges it by thermal contact).
struct ThermalNodes {
  std::vector<double> temperature;  // T_g (g.temperature)
  std::vector<double> rate;         // (dT/dt)_g: conduction + contact (g.temperatureRate)
};

// T_g = sum m_p T_p S / m_g (0 where m_g = 0); sizes t and zeroes t.rate.
void temperature_to_grid(const Particles& p, const Stencils& s, const NodeGrid& g, ThermalNodes& t);

// Adds the conduction rate -1/(c_v m_g) sum_p k V_p grad S_gp . grad T_p to t.rate
// (k the thermal conductivity [W/(m K)], c_v the specific heat [J/(kg K)]).
void add_conduction_rate(const Particles& p, const Stencils& s, const NodeGrid& g, double conductivity,
                         double specific_heat, ThermalNodes& t);

// Thermal contact of all materials (Vaango STThermalContact): every node with
// mass takes the heat-capacity-weighted temperature T_c within the step,
// i.e. (T_c - T_g^m)/dt is added to each material's rate.
void add_thermal_contact_rate(const std::vector<const NodeGrid*>& grids, const std::vector<double>& specific_heat,
                              double dt, std::vector<ThermalNodes*>& thermal);

// T_p += dt sum_g rate_g S_gp.
void temperature_rate_to_particles(const Stencils& s, const ThermalNodes& t, double dt, Particles& p);

// The explicit (forward Euler) stability limit of the conduction step for
// thermal diffusivity alpha = k/(rho c_v): dt <= 1 / (2 alpha sum_d 1/h_d^2),
// the bound of the lumped-mass linear-element Laplacian (largest eigenvalue
// 4 alpha sum_d 1/h_d^2). Infinity for alpha = 0.
double conduction_stable_timestep(double diffusivity, const Vec3& h);

}  // namespace tephra
