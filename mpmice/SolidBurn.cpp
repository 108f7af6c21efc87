// The common part of the MPMICE burn models (mpmice/SolidBurn.h): surface
// cells, the temperature a law sees, the particle side and the sources.
// Facts from Uintah's HEChem Simple_Burn::computeModelSources (read, not
// copied): the surface test on the corner values w_n m_n (SimpleBurn.h), the
// burning temperature = the highest start-of-step temperature among the
// materials that fill more than 20 % of the cell and exceed ThresholdTemp,
// the pressure = press_equil_CC, the cap at the solid's cell mass, and the
// source terms (momentum, c_v T energy, specific volume dm v_s, Enthalpy to
// the product). Uintah's MaxMass > d_TINY_RHO uses 1e-12 (kg) as "a solid is
// there"; so does this.
#include "mpmice/SolidBurn.h"

#include <algorithm>
#include <stdexcept>

#include "core/grid/Loop.h"
#include "ice/IceSetup.h"
#include "mpmice/AxisymmetricBurn.h"
#include "mpmice/SimpleBurn.h"

namespace tephra {

namespace {
constexpr double kTinyCornerMass = 1e-12;  // Uintah's d_TINY_RHO in the surface test [kg]
constexpr double kBurnThetaMin = 0.2;      // a material counts for the burning temperature above this volume fraction
}  // namespace

SolidBurnModel::SolidBurnModel(std::string type, std::string label_prefix, std::size_t reactant, std::size_t product,
                               double enthalpy, double threshold_temperature)
    : type_(std::move(type)),
      prefix_(std::move(label_prefix)),
      reactant_(reactant),
      product_(product),
      enthalpy_(enthalpy),
      threshold_temperature_(threshold_temperature) {}

void SolidBurnModel::initialize(const Grid& grid, const std::vector<IceMaterialFields>&) {
  dm_ = CellScalars(grid, 0);
  on_surface_ = CellScalars(grid, 0);
  burning_ = CellScalars(grid, 0);
  ppc_ = CellScalars(grid, 1);
  burned_.mass = CellScalars(grid, 0);
  burned_.energy = CellScalars(grid, 0);
  burned_.momentum = CellVectors(grid, 0);
  for (CellScalars* f : {&dm_, &on_surface_, &burning_}) f->fill(0.0);
  sums_.reset(grid, 3);
}

void SolidBurnModel::compute_sources(const IceModelInput& in, IceModelSources& out) {
  if (!support_) throw std::logic_error(type_ + ": burn model not attached to an MPMICE component");
  const Grid& g = in.grid;
  const double V = g.cell_volume();
  const Vec3 dx = g.dx;
  dm_.fill(0.0);
  on_surface_.fill(0.0);
  burning_.fill(0.0);
  const IceMaterialFields& solid = in.mats[reactant_];
  // Axisymmetric: per-radian masses, volumes and areas (mpmice/AxisymmetricBurn.h).
  const bool axi = support_->axisymmetric();
  ppc_.fill(0.0);
  support_->particles_per_cell(reactant_, ppc_);
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const IntVec3 c(i, j, k);
      double wm[8];
      support_->corner_masses(reactant_, c, wm);
      BurnCell cell;
      cell.in = &in;
      cell.patch = pi;
      cell.c = c;
      const double r_c = axisymmetric_cell_radius(g.lower[0], dx[0], i);
      cell.volume = axi ? r_c * dx[0] * dx[1] : V;
      cell.solid_mass = solid.rho_CC[pi](c) * cell.volume;
      cell.particles = ppc_[pi](c);
      if (!select_cell(wm, cell)) return;
      if (cell.surface) {
        const Vec3 n = simple_burn_surface_normal(wm, dx);
        const double a = simple_burn_surface_area(n, dx);
        cell.area = axi ? axisymmetric_burn_area(a, n, r_c, dx) : a;
      }
      on_surface_[pi](c) = cell.area;
      dm_[pi](c) = std::clamp(burn_mass(cell), 0.0, cell.solid_mass);
    });
  support_->burn_particles(reactant_, dm_, burned_);
  total_burned_ = total_heat_ = 0;
  total_momentum_ = Vec3::Zero();
  sums_.zero();
  for (std::size_t pi = 0; pi < g.patches.size(); ++pi)
    for_each_cell_serial(g.patches[pi].cells(), [&](int i, int j, int k) {
      const IntVec3 c(i, j, k);
      const double dm = burned_.mass[pi](c);
      if (!(dm > 0)) return;
      const Vec3 P = burned_.momentum[pi](c);
      const double E = burned_.energy[pi](c), dv = dm * solid.sp_vol_CC[pi](c);
      const double heat = dm * heat_of_reaction(pi, c);
      // ICE's contents: Cartesian; per radian (axisymmetric) x dz / r_c.
      const double to_ice = axi ? axisymmetric_content_per_radian_mass(axisymmetric_cell_radius(g.lower[0], dx[0], i), dx[2])
                           : 1.0;
      out.mass[reactant_][pi](c) -= to_ice * dm;
      out.mass[product_][pi](c) += to_ice * dm;
      out.momentum[reactant_][pi](c) -= to_ice * P;
      out.momentum[product_][pi](c) += to_ice * P;
      out.energy[reactant_][pi](c) -= to_ice * E;
      out.energy[product_][pi](c) += to_ice * (E + heat);
      out.sp_vol[reactant_][pi](c) -= to_ice * dv;
      out.sp_vol[product_][pi](c) += to_ice * dv;
      burning_[pi](c) = 1.0;
      total_burned_ += dm;
      total_momentum_ += P;
      total_heat_ += heat;
      sums_.at(pi, 0) += dm;
      sums_.at(pi, 1) += heat;
      sums_.at(pi, 2) += E;
    });
}

bool SolidBurnModel::select_cell(const double wm[8], BurnCell& cell) const {
  if (!simple_burn_surface_cell(wm, kTinyCornerMass)) return false;
  const IceModelInput& in = *cell.in;
  double T = 0;
  for (std::size_t m = 0; m < in.mats.size(); ++m) {
    const double Tm = in.mats[m].temp_CC[cell.patch](cell.c);
    if (in.mats[m].vol_frac_CC[cell.patch](cell.c) > kBurnThetaMin && Tm > threshold_temperature_ && Tm > T) T = Tm;
  }
  cell.temperature = T;
  cell.pressure = in.press_equil_CC[cell.patch](cell.c);
  return true;
}

std::set<std::string> SolidBurnModel::labels() const {
  return {"totalMassBurned", "totalHeatReleased", prefix_ + ".onSurface", prefix_ + ".BurningCell"};
}

std::vector<ModelField> SolidBurnModel::fields() const {
  return {{prefix_ + ".onSurface", 0, &on_surface_}, {prefix_ + ".BurningCell", 0, &burning_}};
}

}  // namespace tephra
