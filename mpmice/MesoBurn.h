#pragma once
// The particle induction clock of <Model type="MesoBurn"> (Uintah's
// HEChem/MesoBurn.cc, read for the rules and names; used by
// mpmice/MesoBurnModel.cpp). MesoBurn is Steady_Burn's WSB surface burning
// (mpmice/SteadyBurn.h, WsbSurfaceCell.h) ignited per particle: each
// reactant particle p carries
//   tau_p  its induction time, relaxed every step towards
//          tau(T_p) = T_p^2 Cv/(Ta Qc) exp(Ta/T_p)/k   (a thermal-explosion time):
//          tau_p <- 0.99 tau_p + 0.01 tau(T_p),  tau_p = 3.1536e13 s at the start
//          (Uintah's ONE_YEAR_MICROSECONDS, used as seconds);
//   t_p    the time it has spent above 470 K: t_p <- t_p + dt when T_p > 470 K.
// Particle p is induced when t_p > tau_p; a cell's `induced` is the count of
// its induced particles / <resolution> (default 8), `inducedMass` their mass.
// T_p and m_p are the start-of-step values.
namespace tephra {

constexpr double kMesoInitialInductionTime = 3.1536e13;  // [s]
constexpr double kMesoInductionTemperature = 470.0;      // [K], Uintah's fixed value

struct MesoInduction {
  double Ta = 0;  // <Ta> activation temperature [K]
  double k = 0;   // <k> rate constant [1/s]
  double Cv = 0;  // <Cv> [J/(kg K)]
  double Qc = 0;  // <CondPhaseHeat> [J/kg]
};

// tau(T) = T^2 Cv/(Ta Qc) exp(Ta/T)/k [s].
double meso_induction_time(const MesoInduction& prm, double T);

struct MesoClock {
  double tau = kMesoInitialInductionTime;  // [s]
  double time_induced = 0;                 // [s]
};

// One step of a particle's clock at temperature T; true when the particle is
// induced after it (t_p > tau_p).
bool meso_advance_clock(MesoClock& clock, const MesoInduction& prm, double T, double dt);

}  // namespace tephra
