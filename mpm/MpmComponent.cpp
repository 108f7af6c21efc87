#include "mpm/MpmComponent.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include <Eigen/LU>

#include "core/base/Errors.h"
#include "core/base/Log.h"
#include "core/base/PhaseTimers.h"
#include "mpm/ArtificialViscosity.h"
#include "mpm/Axisymmetric.h"
#include "mpm/SymmetryFold.h"
#include "mpm/DeformationGradient.h"
#include "mpm/StableTimestep.h"
#include "mpm/StrainWork.h"
#include "mpm/GridDamping.h"
#include "mpm/ParticleReorder.h"
#include "mpm/PressureStabilization.h"
#include "mpm/Transfers.h"
#include "mpm/UpdatedGridVelocity.h"
#include "mpm/contact/ContactNormals.h"
#include "mpm/contact/FrictionHeating.h"
#include "mpm/mms/MmsInitialSize.h"
#include "mpm/loads/BodyForceStress.h"

namespace tephra {

namespace {
// Directions whose symmetry faces fold (mpm/SymmetryFold.h): all three, or r and z
// when axisymmetric (the hoop faces' two node planes carry the hoop weights).
int fold_dims(const MpmFlags& flags) { return flags.axisymmetric ? 2 : 3; }
}  // namespace

MpmComponent::MpmComponent(MpmSetup setup) : setup_(std::move(setup)) {
  const Grid& g = setup_.grid;
  // Ghost node layers of the periodic directions (mpm/PeriodicGrid.h; none there for linear).
  IntVec3 ghost = IntVec3::Zero();
  for (int d = 0; d < 3; ++d)
    if (g.periodic[d]) ghost[d] = std::max(0, periodic_ghost_layers(setup_.flags.interpolator.kind));
  for (MpmMaterial& m : setup_.materials) {
    // Nodes of the interior and extra cells (or periodic ghosts): node 0 at lower - extra*dx.
    m.grid.extra = g.extra_cells + ghost;
    m.grid.ghost = ghost;
    m.grid.origin = g.lower - (m.grid.extra.cast<double>().array() * g.dx.array()).matrix();
    m.grid.h = g.dx;
    m.grid.n = g.cells + 2 * m.grid.extra + IntVec3::Ones();
    // A periodic face is not a domain boundary: no BC there (as ICE, ice/IceDeck.cpp, and Uintah).
    for (int d = 0; d < 3; ++d)
      if (g.periodic[d])
        for (int f : {2 * d, 2 * d + 1}) {
          m.bcs.face[f] = FaceVelocityBC{};
          m.bcs.temperature[f].reset();
        }
    // The friction contacts read g.stressFS (CoulombExchangeLoop.h): always summed with contact.
    m.grid.node_stress = setup_.node_stress || (setup_.contact && setup_.materials.size() > 1);
    m.grid.reset();
  }
  if (!setup_.materials.empty()) periodic_ = periodic_nodes(g, setup_.materials.front().grid);
  boundary_force_.fill(Vec3::Zero());
  boundary_area_.fill(0.0);
}

void MpmComponent::initialize() {
  long long next_id = 0;
  for (MpmMaterial& m : setup_.materials) {
    m.particles = Particles{};
    seed_particles(setup_.grid, m.sources, m.density, m.particles, next_id);
    if (setup_.flags.axisymmetric) make_axisymmetric_particles(setup_.grid.dx, m.density, m.particles);  // per radian
    if (m.mms) {
      initialize_mms_particles(*m.mms, m.particles);  // x = X + u(X,0), v, F at t = 0
      // Vaango's initial p.size (AxisAligned: the deformed domain at t = 0,
      // kept fixed by gimp; mpm/mms/MmsInitialSize.h). Not for the
      // domains F p.size (cpdi, cpti, cpgimp: F(X,0) is already in F).
      const InterpolatorKind k = setup_.flags.interpolator.kind;
      const bool domain_is_F_size =
          k == InterpolatorKind::Cpdi || k == InterpolatorKind::Cpti || k == InterpolatorKind::CpGimp;
      if (mms_deformed_initial_size(*m.mms) && !domain_is_F_size && !setup_.flags.axisymmetric) {
        // uGIMP's weights (eqs. 1.90-1.92) hold for a half-length l <= h/2:
        // at 1 particle per cell the deformed size l0 F_dd(X,0) exceeds it
        // (Vaango's formula then gives weights above 1), so Tephra keeps the
        // seeded size there and says so.
        const double max_size = k == InterpolatorKind::Gimp ? 1.0 : std::numeric_limits<double>::infinity();
        if (!set_mms_deformed_initial_size(*m.mms, m.particles, max_size))
          log::warning("run_MMS_problem " + m.mms->name() +
                  ": the deformed initial particle size (Vaango: size F(X,0)) exceeds one cell, outside the "
                  "uGIMP weights' range l <= h/2; the seeded size is kept (docs/mpm-convergence.md)");
      }
    }
    // The model's history columns at their declared initial values.
    m.particles.history.clear();
    for (const HistoryVariable& h : m.model->history()) {
      std::vector<double> column;
      column.reserve(m.particles.size() * h.initial.size());
      for (std::size_t i = 0; i < m.particles.size(); ++i) column.insert(column.end(), h.initial.begin(), h.initial.end());
      m.particles.history.push_back(std::move(column));
    }
  }
  // Under mpirun: patches to ranks, each rank keeps the particles of its patches (mpm/MpmRanks.cpp).
  lay_out_patches();
  for (MpmMaterial& m : setup_.materials) {
    // <initialize_stress_using_body_force>: sigma, F and V of eqs. (1), (2) of mpm/loads/BodyForceStress.h.
    if (setup_.flags.initialize_stress_using_body_force && m.body_force_surface)
      initialize_stress_from_body_force(m.density, setup_.gravity, *m.body_force_surface, m.model->bulk_modulus(),
                                        m.model->shear_modulus(), m.particles);
    m.F_old = m.particles.F;
    m.L.assign(keeps_L(m) ? m.particles.size() : 0, Mat3::Zero());
    update_stress(m, 0, 0.0);  // sigma(F = I) = 0, and the initial wave speeds
  }
  apply_loads(0.0);
  set_node_boxes();
  for (MpmMaterial& m : setup_.materials) project_to_grid(m, 0, "initialize");  // g.* fields of the initial state
  // The first step's size from the initial state (Vaango: the constitutive
  // model's computeStableTimestep at initialization, c(F = I) and v_0).
  stable_dt_ = std::numeric_limits<double>::infinity();
  for (const MpmMaterial& m : setup_.materials) stable_dt_ = std::min(stable_dt_, material_stable_timestep(m));
  stable_dt_ = std::min(stable_dt_, thermal_stable_timestep());
  time_ = 0.0;
  acc_strain_energy_ = 0.0;
  plastic_work_ = 0.0;
  ledger_ = EnergyLedger{};
}

// Vaango's explicit rule (UCNH::computeStressTensor, called by SerialMPM's
// computeStressTensor task): the step size is a by-product of the stress
// update of step n, evaluated from the NEW stress state and the OLD particle
// velocity, and used (times timestep_multiplier) for step n+1:
//   dt = min_d h_d / max_p (c_p + |v_p,d|),
// c_p = c(F_{n+1}) the dilatational wave speed of the model, v_p = v_n the
// velocity the particle carried into step n (SerialMPM updates it only later,
// in interpolateToParticlesAndUpdate). Infinity when there are no particles.
// (mpm/StableTimestep.h: one division per direction, the bits of the
// quotient-by-quotient minimum).
double MpmComponent::material_stable_timestep(const MpmMaterial& m) const {
  const double dt = particle_stable_timestep(m.particles, setup_.grid.dx);
  return layout_.min(dt);  // over the MPI ranks (exact: every rank gets the one-process value)
}

// The step size computed by the last stress update (initialize() or advance()).
double MpmComponent::stable_timestep() const { return stable_dt_; }

// max_p,d dt (c_p + |v_p,d|) / h_d of a material: the Courant number of this step.
double MpmComponent::courant_number(const MpmMaterial& m, double dt) const {
  return dt / material_stable_timestep(m);
}

void MpmComponent::fail_particle(const MpmMaterial& m, std::size_t i, int step, const std::string& phase,
                                 const std::string& what) const {
  const Particles& p = m.particles;
  std::ostringstream s;
  s.precision(17);
  s << "MPM step " << step << ", " << phase << ": material " << m.index << " particle id " << p.id[i]
    << " at (" << p.x[i][0] << ", " << p.x[i][1] << ", " << p.x[i][2] << "): " << what;
  throw NumericalFailure(s.str());
}

// Stencils + P2G (Alg. 5) on a reset grid, with the grid BCs on v_g.
void MpmComponent::interpolate_to_grid(MpmMaterial& m, int step, const char* phase, bool may_reorder,
                                       bool with_internal_force) {
  PhaseTimers::Scope t(phase_timers(), "MPM: interpolate particles to grid");
  // The per-axis stencil form (Interpolator.h) for linear, gimp and
  // 3rdorderBS when every support is inside the grid, not axisymmetric and no
  // contact model reads the stencils by entry index (friction_LR); else the
  // flat form. Transfers, heat conduction and contact normals read either.
  const bool axis_form = !setup_.flags.axisymmetric && !(setup_.contact && setup_.materials.size() > 1) &&
                         compute_axis_stencils(m.particles, m.grid, setup_.flags.interpolator, m.stencils);
  const long bad = axis_form ? -1
                   : setup_.flags.axisymmetric
                       ? compute_axisymmetric_stencils(m.particles, m.grid, setup_.flags.interpolator.kind, m.stencils)
                       : compute_stencils(m.particles, m.grid, setup_.flags.interpolator, m.stencils);
  if (bad >= 0) fail_particle(m, std::size_t(bad), step, phase, "particle is outside the grid");
  PatchBand* band = prepare_band(m);  // also orders each block by particle id (ScatterOrder::sort_blocks_by_id)
  // Columns into the scatter order when enough particles changed block
  // (mpm/ParticleReorder.h), then the stencils of the new order (index = identity).
  // Not with MPMICE (its per-particle arrays are not permuted here).
  if (axis_form && may_reorder && setup_.reorder_particles && !coupling_ &&
      reorder_worthwhile(m.stencils.order, m.particles.size())) {
    PhaseTimers::Scope r(phase_timers(), "MPM: reorder particles");
    reorder_particles(m);
    compute_axis_stencils(m.particles, m.grid, setup_.flags.interpolator, m.stencils);
    if (band) m.stencils.order.sort_blocks_by_id(m.particles.id.data());
  }
  // The threaded scatters' particle order (compute_stencils / compute_axis_stencils build their own).
  if (!axis_form && setup_.flags.axisymmetric) order_scatter(m.grid, m.stencils);
  m.grid.reset();
  if (with_internal_force && !setup_.flags.axisymmetric)
    particles_to_grid_and_internal_force(m.particles, m.stencils, setup_.gravity, m.grid, band);  // f_int,g too (Alg. 6)
  else
    particles_to_grid(m.particles, m.stencils, setup_.gravity, m.grid, band);
  sum_particles_to_grid(m.grid);  // over the MPI ranks (mpm/MpmRanks.cpp; no-op in one process)
  fold_particle_sums(periodic_, m.grid);  // periodic aliases share the sums
  // Symmetry faces as mirrors: extra-cell sums onto their mirror nodes (mpm/SymmetryFold.h;
  // axisymmetric runs: the r and z faces, not the hoop faces).
  fold_symmetry_particle_sums(m.bcs, m.grid, fold_dims(setup_.flags));
  m.bcs.apply(m.grid, m.grid.velocity);
  copy_from_canonical(periodic_, m.grid.velocity);  // the ghosts follow their images
}

// The band of mpm/PatchBand.h for several patches, not periodic (the alias
// folds would add sums of other patches' partials) and not axisymmetric (its
// internal force is not band-summed yet). Reach: a per-axis stencil of N
// nodes holds the particle's cell nodes c or c + 1, so it lies in
// [c - (N - 2), c + 1 + (N - 2)]; one node more covers a position on a cell
// face (patch_of's cell against the stencil's). Flat stencils: the widest
// footprint, which holds the cell nodes as well. On ranks the widest over all
// ranks, so that every rank builds the same band.
PatchBand* MpmComponent::prepare_band(MpmMaterial& m) {
  band_used_ = setup_.grid.patches.size() > 1 && !periodic_.active() && !setup_.flags.axisymmetric;
  if (!band_used_) return nullptr;
  const ScatterOrder& o = m.stencils.order;
  int reach = o.built_for(m.particles.size()) ? (m.stencils.axis_nodes ? o.span - 1 : o.span) : 0;
  if (layout_.distributed) reach = int(-layout_.min(-double(reach)));
  band_request_ = std::max(band_request_, reach);  // monotone: coupling_band(extra) then stops growing the band
  band_.prepare(setup_.grid, m.grid, reach);
  m.stencils.order.sort_blocks_by_id(m.particles.id.data());
  return &band_;
}

PatchBand* MpmComponent::coupling_band(int extra) {
  if (!band_used_ || setup_.materials.empty()) return nullptr;
  int reach = band_request_ + extra;
  if (layout_.distributed) reach = int(-layout_.min(-double(reach)));  // the widest over the ranks
  band_.prepare(setup_.grid, setup_.materials.front().grid, reach);
  return &band_;
}

void MpmComponent::reorder_particles(MpmMaterial& m) {
  const std::vector<std::uint32_t>& order = m.stencils.order.index;
  // F_old is dead here: step 9 swaps it with F and overwrites F (advance()); its memory is the scratch.
  permute_particles(m.particles, order, m.F_old);
  std::byte* scratch = reinterpret_cast<std::byte*>(m.F_old.data());
  // L is dead too (step 9 recomputes it); the model outputs and the
  // velocity-surface flags of this step (prescribe_surface_velocities) move with their particles.
  permute_column(m.plastic_work, order, scratch);
  permute_column(m.heating, order, scratch);
  const std::size_t mi = std::size_t(&m - setup_.materials.data());
  if (mi < surface_of_particle_.size()) permute_column(surface_of_particle_[mi], order, scratch);
}

// P2G + internal force (Alg. 5-6): the g.* fields of the initial state.
void MpmComponent::project_to_grid(MpmMaterial& m, int step, const char* phase) {
  interpolate_to_grid(m, step, phase);
  PhaseTimers::Scope t(phase_timers(), "MPM: compute internal force");
  internal_force(m);
}

// f_int,g (Alg. 6; with the hoop term when axisymmetric), summed over periodic aliases.
// scattered: the sum over the particles was taken by P2G (particles_to_grid_and_internal_force).
void MpmComponent::internal_force(MpmMaterial& m, bool scattered) {
  if (setup_.flags.axisymmetric) axisymmetric_internal_force(m.particles, m.stencils, m.grid);
  else if (!scattered) compute_internal_force(m.particles, m.stencils, m.grid, band());
  if (band() && !setup_.flags.axisymmetric) keep_band_on_one_rank(m.grid.internal_force.front().data(), 3);
  sum_node_vectors(m.grid.internal_force);  // over the MPI ranks
  fold_internal_force(periodic_, m.grid);
  fold_symmetry_internal_force(m.bcs, m.grid, fold_dims(setup_.flags));
}

bool MpmComponent::keeps_L(const MpmMaterial& m) const {
  return m.model->reads_velocity_gradient() || setup_.flags.artificial_viscosity || setup_.flags.axisymmetric ||
         deformation_gradient_algorithm(setup_.flags.deformation_gradient) != DeformationGradientAlgorithm::FirstOrder;
}

// sigma_{n+1}, c, W, history from (F_n, F_{n+1}, l, sigma_n) (Alg. 11); V_{n+1} = J V0 (Alg. 9).
void MpmComponent::update_stress(MpmMaterial& m, int step, double dt) {
  PhaseTimers::Scope t(phase_timers(), "MPM: compute stress tensor");
  Particles& p = m.particles;
  const long np = static_cast<long>(p.size());
  long bad_J = np;  // the lowest particle with det F <= 0 (what the serial loop reports)
#pragma omp parallel for schedule(static) reduction(min : bad_J) if (np >= 4096)
  for (long i = 0; i < np; ++i) {
    const double J = p.F[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) bad_J = std::min(bad_J, i);
    else p.volume[i] = J * p.volume0[i];
  }
  if (bad_J < np) {
    std::ostringstream s;
    s << "Jacobian det F = " << p.F[bad_J].determinant() << " (must be > 0)";
    fail_particle(m, std::size_t(bad_J), step, "compute deformation gradient", s.str());
  }
  m.plastic_work.resize(p.size());
  m.heating.resize(p.size());
  std::vector<std::span<double>> history(p.history.begin(), p.history.end());
  SolidUpdateInput in;
  in.dt = dt;
  in.density0 = m.density;
  in.F_old = m.F_old;
  in.F_new = p.F;
  in.L = m.L;
  in.temperature = p.temperature;
  in.stress_old = p.stress;
  in.position = p.x;       // x_p at t_n (the particles move after the stress update)
  in.time = time_ + dt;    // t_{n+1}; time_ is t_n here (0 at initialization)
  in.reference_volume = p.volume0;
  const SolidUpdateOutput out{p.stress, p.wave_speed, p.energy_density, m.plastic_work, m.heating, history};
  const long bad = m.model->update(in, out);
  if (bad >= 0) fail_particle(m, std::size_t(bad), step, "compute stress tensor",
                              "constitutive model '" + m.model->type() +
                                  "' rejected the state (non-finite stress or no real wave speed)");
  if (setup_.flags.erosion != ErosionAlgorithm::None) erode(m);  // failed particles (mpm/Erosion.h)
  if (setup_.flags.artificial_viscosity) artificial_viscosity(m);
}

// q_p from this step's l_p and the current density (mpm/ArtificialViscosity.h),
// for the internal force of the next step; with <artificial_viscosity_heating>
// also the heating rate -q tr D / (rho c_v) (Vaango's Tdot_AV).
void MpmComponent::artificial_viscosity(MpmMaterial& m) const {
  Particles& p = m.particles;
  const Vec3& dx = setup_.grid.dx;
  const double h = (dx[0] + dx[1] + dx[2]) / 3.0;
  const ArtificialViscosityCoefficients a{setup_.flags.artificial_viscosity_coeff1,
                                          setup_.flags.artificial_viscosity_coeff2};
  const double K = m.model->bulk_modulus();
  for (std::size_t i = 0; i < p.size(); ++i) {
    const double rho = p.mass[i] / p.volume[i];
    const double trace_D = m.L[i].trace();
    p.q[i] = artificial_bulk_viscosity(trace_D, std::sqrt(K / rho), rho, h, a);
    if (setup_.flags.artificial_viscosity_heating && m.specific_heat > 0.0)
      m.heating[i] += -p.q[i] * trace_D / (rho * m.specific_heat);
  }
}

// Contact on v_g (interpolated) or v*_g (integrated) of all materials (§1.7).
// The normals and positions depend on the particles of step n only, so they
// are computed once, at the interpolated stage, and reused.
void MpmComponent::exchange_momentum(ContactStage stage, double t, double dt, bool record_work) {
  const ContactModel& model = *setup_.contact;
  if (!model.acts_on(stage) && !(stage == ContactStage::Interpolated)) return;
  PhaseTimers::Scope timer(phase_timers(), stage == ContactStage::Interpolated
                                               ? "MPM: contact (interpolated)"
                                               : "MPM: contact (integrated)");
  ContactNodes& c = contact_nodes_;
  auto& mats = setup_.materials;
  if (stage == ContactStage::Interpolated) {
    c.grid.clear();
    for (const MpmMaterial& m : mats) c.grid.push_back(&m.grid);
    c.particles.clear();
    c.stencils.clear();
    for (const MpmMaterial& m : mats) c.particles.push_back(&m.particles), c.stencils.push_back(&m.stencils);
    c.h = setup_.grid.dx;
    for (int f = 0; f < 6; ++f)
      c.symmetry_face[f] = !mats.empty() && f < 2 * fold_dims(setup_.flags) &&
                           mats[0].bcs.face[f].kind == FaceVelocityBC::Kind::Symmetry;
    c.canonical = periodic_.active() ? &periodic_.canonical : nullptr;
    c.t = t;
    c.dt = dt;
    c.gradient.resize(model.needs_normals() ? mats.size() : 0);
    c.position.resize(model.needs_positions() ? mats.size() : 0);
    for (std::size_t i = 0; i < c.gradient.size(); ++i) mass_gradient(mats[i].particles, mats[i].stencils, mats[i].grid, c.gradient[i]);
    for (std::size_t i = 0; i < c.position.size(); ++i)
      if (periodic_.active()) mass_weighted_offset(mats[i].particles, mats[i].stencils, mats[i].grid, c.position[i]);
      else mass_weighted_position(mats[i].particles, mats[i].stencils, mats[i].grid, c.position[i]);
    // Over the MPI ranks: both divide by the global m_g already, so the per-rank results add.
    for (std::vector<Vec3>& n : c.gradient) sum_node_vectors(n);
    for (std::vector<Vec3>& n : c.position) sum_node_vectors(n);
    // Periodic aliases (mpm/PeriodicGrid.h): normals summed, positions folded as offsets.
    for (std::vector<Vec3>& n : c.gradient) fold_vectors(periodic_, n);
    // Symmetry faces: the mirrored particles' share of the gradients (ContactNormals.h).
    for (std::size_t i = 0; i < c.gradient.size(); ++i)
      mirror_gradient_at_symmetry_faces(mats[i].bcs, mats[i].grid, c.gradient[i], fold_dims(setup_.flags));
    for (std::size_t i = 0; i < c.position.size(); ++i) fold_positions(periodic_, mats[i].grid, c.position[i]);
    // <collinear_bimaterial_contact_normals>: body-averaged normals (ContactNormals.h).
    if (setup_.flags.collinear_contact_normals) collinear_normals(c.grid, c.gradient);
    // <do_contact_friction_heating>: the work of this step's two contact stages (FrictionHeating.h).
    c.friction_work.assign(setup_.flags.contact_friction_heating ? mats.size() : 0,
                           std::vector<double>(mats.empty() ? 0 : mats[0].grid.count(), 0.0));
    p2g_velocity_.resize(mats.size());
    for (std::size_t i = 0; i < mats.size(); ++i) p2g_velocity_[i] = mats[i].grid.velocity;
    if (!model.acts_on(stage)) return;
  }
  c.velocity.clear();
  for (MpmMaterial& m : mats)
    c.velocity.push_back(stage == ContactStage::Interpolated ? &m.grid.velocity : &m.grid.velocity_star);
  if (record_work) {
    model.exchange(stage, c);
  } else {
    std::vector<std::vector<double>> work;
    std::swap(work, c.friction_work);
    model.exchange(stage, c);
    std::swap(work, c.friction_work);
  }
}

// Vaango's boundary reactions (SerialMPM::computeInternalForce): for each
// requested domain face, BndyForce = -sum f_int over the nodes on the face,
// all materials (Vaango's sign: minus the internal force, so a body in
// uniform stress sigma touching the face gives -sigma . n_in A with n_in the
// inward normal; e.g. on z- a compressed body gives +|sigma_zz| A), and
// BndyContactArea = sum V_g / h_d over the same nodes (d the face normal).
void MpmComponent::boundary_forces() {
  // On MPI ranks every rank sums whole-grid copies of f_int and V_g (the same
  // nodes in the same order as one process).
  std::vector<std::vector<double>> whole_force, whole_volume;
  if (layout_.distributed && !setup_.flags.boundary_traction_faces.empty())
    for (const MpmMaterial& m : setup_.materials) {
      whole_force.push_back(node_sums_.whole(m.grid.internal_force.front().data(), 3));
      whole_volume.push_back(node_sums_.whole(m.grid.volume.data(), 1));
    }
  for (int f : setup_.flags.boundary_traction_faces) {
    const int d = f / 2;
    Vec3 force = Vec3::Zero();
    double area = 0.0;
    for (std::size_t mi = 0; mi < setup_.materials.size(); ++mi) {
      // The domain's face nodes (Vaango's Patch::FaceNodes): the node plane
      // extra or n - 1 - extra, over the interior nodes of the other two
      // directions (not the extra-cell nodes that GIMP/CPDI/B-splines reach).
      const NodeGrid& g = setup_.materials[mi].grid;
      const double* fint = whole_force.empty() ? g.internal_force.front().data() : whole_force[mi].data();
      const double* vol = whole_volume.empty() ? g.volume.data() : whole_volume[mi].data();
      const int plane = (f % 2 == 0) ? g.extra[d] : g.n[d] - 1 - g.extra[d];
      const int a = (d + 1) % 3, b = (d + 2) % 3;
      IntVec3 c;
      c[d] = plane;
      for (c[b] = g.extra[b]; c[b] < g.n[b] - g.extra[b]; ++c[b])
        for (c[a] = g.extra[a]; c[a] < g.n[a] - g.extra[a]; ++c[a]) {
          const std::size_t gi = g.index(c);
          force -= Vec3(fint[3 * gi], fint[3 * gi + 1], fint[3 * gi + 2]);
          area += vol[gi] / g.h[d];
        }
    }
    boundary_force_[f] = force;
    boundary_area_[f] = area;
  }
}

// f_ext,p of every particle from the deck's <PhysicalBC> loads at time t (mpm/loads/).
void MpmComponent::apply_loads(double t) {
  if (setup_.loads.empty()) return;
  PhaseTimers::Scope timer(phase_timers(), "MPM: apply external loads");
  std::vector<Particles*> particles;
  for (MpmMaterial& m : setup_.materials) particles.push_back(&m.particles);
  apply_particle_loads(setup_.loads, t, setup_.grid.dx, particles, load_totals());  // N, sum d^2 over the ranks
}

// One explicit USL step of all materials, in the order of Algorithm 2 of the
// Vaango theory manual (§1.9). Each phase runs over every material before the
// next starts, so that contact sees the node values of all of them. With one
// material or null contact there is no contact pass. Every phase works with
// the stencils of <MPM><interpolator> (linear, gimp, cpdi, 3rdorderBS), and
// the grid BCs also set the extra-cell nodes those reach.
void MpmComponent::advance(double t, double dt, int step) {
  stable_dt_ = std::numeric_limits<double>::infinity();
  auto& mats = setup_.materials;
  const bool contact = setup_.contact && mats.size() > 1;

  // 0. External loads on the particles: the manufactured solution's body
  //    force f_ext,p = m_p b(X_p, t_n) (Vaango: at the step's start time).
  //    The update v_{n+1} = v_n + dt a(x_n), x_{n+1} = x_n + dt v_{n+1} is the
  //    leapfrog scheme when v_n is read as v(t_n - dt/2): second order in dt
  //    only if the start velocity is v(-dt_0/2). Vaango starts from v(0),
  //    which leaves an O(dt) = O(h) displacement error (docs/mpm-convergence.md:
  //    at 16^3 it moves with dt; with v(-dt_0/2) it does not); so the first
  //    step (t = 0; a restart resumes at t > 0) replaces v(0) by v(-dt_0/2).
  for (MpmMaterial& m : mats)
    if (m.mms) {
      PhaseTimers::Scope timer(phase_timers(), "MPM: apply external loads");
      if (t == 0.0) set_mms_velocity(*m.mms, -0.5 * dt, m.particles);
      apply_mms_body_force(*m.mms, t, m.particles);
    }
  //    <PhysicalBC> pressure and force loads at t_n with F_n (Vaango's applyExternalLoads).
  apply_loads(t);
  //    Rotating frame: f_ext,p += m_p (-omega x (omega x r) - 2 omega x v) at x_n, v_n (Alg. 3, mpm/loads/RotatingFrame.h).
  if (setup_.rotating_frame) apply_rotating_frame();
  //    <PhysicalBC><MPM><velocity>: v_p = v(t_n) on the flagged particles (mpm/loads/VelocityBcPhase.cpp).
  const bool velocity_surfaces = !setup_.loads.velocity.empty();
  if (velocity_surfaces) prescribe_surface_velocities(t);
  // 1-3. Body force (gravity) and external loads enter P2G: m_g, V_g, v_g, f_ext,g (Alg. 5, eq. 1.69).
  //      On MPI ranks: first the node boxes the node sums combine over (mpm/MpmRanks.cpp).
  set_node_boxes();
  // 1-3 and 5 in one pass over the particles (the same node sums, the same bits)
  // when nothing in between changes sigma_p, V_p, q_p or f_int,g: no contact, no MPMICE.
  const bool fused_force = !contact && !coupling_ && !setup_.flags.axisymmetric;
  for (MpmMaterial& m : mats) interpolate_to_grid(m, step, "interpolate particles to grid", true, fused_force);
  if (velocity_surfaces) find_surface_velocity_nodes(t);  // v_g = v(t_n) at the nodes they reach
  // MPMICE steps 1-6: node -> cell, equilibration, face velocities, pressure (mpmice/).
  if (coupling_) coupling_->after_interpolate_to_grid(t, dt, step);
  // The kinetic-energy ledger (mpm/EnergyLedger.h): KE_g at each velocity correction of the step.
  const bool ledger = setup_.energy_ledger;
  // On MPI ranks each rank adds this step's terms of the nodes it counts (those
  // of its box no lower rank's box holds: every node with mass once) and of its
  // particles into ledger_step; the four totals are added over the ranks at the
  // end of the step. One process adds straight into ledger_ (its bits unchanged).
  EnergyLedger ledger_step;
  EnergyLedger& ledger_sink = layout_.distributed ? ledger_step : ledger_;
  const std::vector<char> ledger_nodes = ledger && layout_.distributed ? first_holder_nodes() : std::vector<char>{};
  if (ledger) {
    ledger_velocity_.resize(mats.size());
    for (std::size_t i = 0; i < mats.size(); ++i) ledger_velocity_[i][0] = mats[i].grid.velocity;  // v_g
  }
  // 4. Contact on the interpolated velocities v_g.
  if (contact) exchange_momentum(ContactStage::Interpolated, t, dt);
  // 5. f_int,g = -sum V_p sigma_p grad S_gp with sigma, V at t_n (Alg. 6, eq. 1.70).
  {
    PhaseTimers::Scope timer(phase_timers(), "MPM: compute internal force");
    for (MpmMaterial& m : mats) internal_force(m, fused_force);
    if (coupling_) coupling_->add_internal_forces();  // MPMICE: the cell pressure on the particles
    boundary_forces();
  }
  // 5b. Node temperatures and their rates: conduction, thermal contact (mpm/thermal).
  compute_heat_rates(dt);
  // 6. a_g = (f_int + f_ext)/m_g, v*_g = v_g + a_g dt (Alg. 7, eqs. 1.71-1.72).
  {
    PhaseTimers::Scope timer(phase_timers(), "MPM: integrate grid acceleration");
    for (MpmMaterial& m : mats) integrate_grid_velocity(m.grid, dt);
    if (setup_.flags.artificial_damping_coeff > 0.0)  // a_g -= alpha v_g (eq. 1.65, mpm/GridDamping.h)
      for (MpmMaterial& m : mats) apply_grid_damping(m.grid, setup_.flags.artificial_damping_coeff, dt);
  }
  // MPMICE steps 8-13: Lagrangian cell values, exchange, fluid advection; the
  // solid's cell velocity change back to the nodes (mpmice/).
  if (coupling_) coupling_->after_integrate_grid(dt, step);
  if (ledger)
    for (std::size_t i = 0; i < mats.size(); ++i) ledger_velocity_[i][1] = mats[i].grid.velocity_star;  // v*_g
  // 7. Contact on the integrated velocities v*_g.
  if (contact) exchange_momentum(ContactStage::Integrated, t, dt);
  if (ledger)  // v*_g after the integrated contact
    for (std::size_t i = 0; i < mats.size(); ++i) ledger_velocity_[i][2] = mats[i].grid.velocity_star;
  // 8. Grid BCs on v*_g, then a_g = (v*_g - v_g)/dt (Alg. 8). With contact,
  //    v_g is the P2G velocity from before the interpolated contact, so that
  //    the FLIP update v_p += dt sum a_g S carries both contact corrections
  //    to the particles. (Vaango takes a_g against the corrected v_g, which
  //    drops the interpolated-stage correction from the particle velocities:
  //    a block resting on a plane under gravity then keeps the approach
  //    velocity that contact removed on the grid and sinks into the plane.)
  {
    PhaseTimers::Scope timer(phase_timers(), "MPM: set grid boundary conditions");
    for (std::size_t i = 0; i < mats.size(); ++i) {
      MpmMaterial& m = mats[i];
      m.bcs.apply(m.grid, m.grid.velocity_star);
      copy_from_canonical(periodic_, m.grid.velocity_star);
      if (velocity_surfaces) impose_surface_velocities(i, t + dt, m.grid.velocity_star);
      if (contact) {
        for (std::size_t g = 0; g < m.grid.count(); ++g)
          m.grid.acceleration[g] = (m.grid.velocity_star[g] - p2g_velocity_[i][g]) / dt;
      } else {
        acceleration_from_velocities(m.grid, dt);
      }
    }
  }
  if (ledger)  // v_g, v^c_g = g.velocity, v*_g, after contact, v^f_g = g.velocity_star (mpm/EnergyLedger.h)
    for (std::size_t i = 0; i < mats.size(); ++i)
      add_node_terms(mats[i].grid, ledger_velocity_[i][0], mats[i].grid.velocity, ledger_velocity_[i][1],
                     ledger_velocity_[i][2], mats[i].grid.velocity_star, dt, ledger_sink,
                     ledger_nodes.empty() ? nullptr : &ledger_nodes);
  //    <use_prescribed_deformation>: v*_g = l x_g, so that F follows F*(t) (mpm/PrescribedDeformation.h).
  if (setup_.prescribed) {
    const Mat3 l = setup_.prescribed->step_velocity_gradient(t, dt);
    for (MpmMaterial& m : mats) set_prescribed_grid_velocity(l, dt, m.grid);
  }
  // 9. l_p = sum v_g grad S^T, F_{n+1} = (I + dt l) F_n (Alg. 9, eqs. 1.73-1.75);
  //    F_n is kept as the model's input; a rigid material keeps F = I (VT eq. 3.1).
  //    v_g is the P2G of the updated particle velocities (MUSL, mpm/UpdatedGridVelocity.h)
  //    under the same grid BCs and contact as v*_g, not Vaango's v*_g: it stays bounded
  //    at small-mass nodes. A prescribed deformation sets v*_g = l x_g exactly: l_p from v*_g.
  {
    PhaseTimers::Scope timer(phase_timers(), "MPM: compute deformation gradient");
    const bool musl = !setup_.prescribed;
    if (musl) {
      musl_velocity_.resize(mats.size());
      const double cell_volume = setup_.grid.dx[0] * setup_.grid.dx[1] * setup_.grid.dx[2];
      // Axisymmetric: V_g is per radian, so the fill is V_g / V_full(r_g), not V_g / cell_volume
      // (which called a node at r = 10 h_z with a tenth of its material "half full": USL there
      // let the cookoff cap's outer surface nodes run away, docs/validation/cookoff.md "Session 25").
      const std::vector<double>* full_x = nullptr;
      if (setup_.flags.axisymmetric && !mats.empty()) {
        if (usl_full_volume_x_.size() != std::size_t(mats.front().grid.n[0]))
          usl_full_volume_x_ = axisymmetric_full_node_volumes(mats.front().grid);
        full_x = &usl_full_volume_x_;
      }
      // The USL fill limits, once per material (a pass over the particles; v and c do not change in this phase).
      std::vector<double> fill_limit(mats.size());
      for (std::size_t i = 0; i < mats.size(); ++i) fill_limit[i] = usl_fill_limit(courant_number(mats[i], dt));
      for (std::size_t i = 0; i < mats.size(); ++i) {
        MpmMaterial& m = mats[i];
        if (!contact && !periodic_.active()) {
          // Only the nodes keep_stable_usl_nodes keeps below (none: USL everywhere; same bits).
          usl_needed_nodes(m.grid, fill_limit[i], cell_volume, musl_needed_, full_x);
          updated_particle_grid_velocity_at(m.particles, m.stencils, m.grid, dt, musl_needed_, musl_velocity_[i],
                                            band());
        } else {
          updated_particle_grid_velocity(m.particles, m.stencils, m.grid, dt,
                                         periodic_.active() ? &periodic_.canonical : nullptr, musl_velocity_[i],
                                         band());
        }
        if (band()) keep_band_on_one_rank(musl_velocity_[i].front().data(), 3);
        sum_node_vectors(musl_velocity_[i]);  // over the MPI ranks (divided by the global m_g already)
        fold_symmetry_velocity(m.bcs, m.grid, musl_velocity_[i], fold_dims(setup_.flags));
        m.bcs.apply(m.grid, musl_velocity_[i]);
        copy_from_canonical(periodic_, musl_velocity_[i]);
        if (velocity_surfaces) impose_surface_velocities(i, t + dt, musl_velocity_[i]);
        std::swap(m.grid.velocity_star, musl_velocity_[i]);  // l_p and contact read g.velocity_star
      }
      if (contact) exchange_momentum(ContactStage::Integrated, t, dt, false);
      for (std::size_t i = 0; i < mats.size(); ++i) {  // v*_g back where USL is stable for the node
        keep_stable_usl_nodes(mats[i].grid, fill_limit[i], cell_volume,
                              musl_velocity_[i], mats[i].grid.velocity_star, full_x);
        // The node-by-node choice can pick MUSL at an extra node (little volume)
        // and v*_g at its mirror node (full): the grid BCs again, so that the
        // extra nodes mirror the velocity l_p reads. With it a symmetric run is
        // the mirror problem without faces (AxisAligned: equal to the periodic
        // run on [-1, 1]^3; docs/mpm-convergence.md "Session 16").
        mats[i].bcs.apply(mats[i].grid, mats[i].grid.velocity_star);
        if (velocity_surfaces) impose_surface_velocities(i, t + dt, mats[i].grid.velocity_star);
      }
    }
    for (std::size_t i = 0; i < mats.size(); ++i) {
      MpmMaterial& m = mats[i];
      Particles& p = m.particles;
      std::swap(m.F_old, p.F);  // F_n kept as the model's input, without a copy
      // <deformation_gradient algorithm>: first_order is eq. 1.75; the series
      // approximate exp(dt l) (mpm/DeformationGradient.h).
      const DeformationGradientAlgorithm alg = deformation_gradient_algorithm(setup_.flags.deformation_gradient);
      if (!setup_.flags.axisymmetric && alg == DeformationGradientAlgorithm::FirstOrder) {
        if (keeps_L(m)) velocity_gradients_and_first_order_F(m.stencils, m.grid, dt, m.L, m.F_old, p.F);  // one pass, same bits
        else first_order_F(m.stencils, m.grid, dt, m.F_old, p.F);  // the same F, no L column
      } else {
        if (setup_.flags.axisymmetric) axisymmetric_velocity_gradients(m.stencils, m.grid, m.L);  // + v_r / r
        else velocity_gradients(m.stencils, m.grid, m.L);
        update_deformation_gradients(alg, setup_.flags.deformation_gradient_terms, dt, m.L, m.F_old, p.F);
      }
      if (musl) std::swap(m.grid.velocity_star, musl_velocity_[i]);  // G2P moves the particles with v*_g
      if (setup_.flags.pressure_stabilization) {  // eqs. 1.82-1.84 (mpm/PressureStabilization.h)
        std::vector<double> cell_sums = cell_volume_sums(m.grid, p);  // {V_c0, V_c} at each cell's lower node
        sum_node_doubles(cell_sums, 2);  // over the MPI ranks: a cell's particles may sit on two
        apply_cell_dilatation(m.grid, cell_sums, p);
      }
      if (m.model->rigid()) std::fill(p.F.begin(), p.F.end(), Mat3::Identity());
    }
  }
  // 10. sigma_{n+1}, history (Alg. 11); the next step's dt from c(F_{n+1}) and v_n (before the particle update).
  //     AccStrainEnergy += sum V0 (P_n + P_{n+1})/2 : (F_{n+1} - F_n) (mpm/StrainWork.h).
  for (MpmMaterial& m : mats) {
    const bool work = setup_.accumulate_strain_energy;
    if (work) acc_strain_energy_ += 0.5 * sum_over_ranks(piola_work(m.particles, m.F_old, m.F_old));  // sigma_n at F_n
    update_stress(m, step, dt);
    if (setup_.accumulate_plastic_work)  // PlasticWork (mpm/StrainWork.h), only when saved: the same flag on every rank
      plastic_work_ += sum_over_ranks(plastic_work_of_step(m.particles, m.plastic_work));
    if (work) acc_strain_energy_ += 0.5 * sum_over_ranks(piola_work(m.particles, m.particles.F, m.F_old));  // sigma_{n+1} at F_{n+1}
    stable_dt_ = std::min(stable_dt_, material_stable_timestep(m));
  }
  stable_dt_ = std::min(stable_dt_, thermal_stable_timestep());
  //     <PhysicalBC><MPM><heat_flux>: q(t_n) A / N per flagged particle into its heating rate (mpm/loads/BodyForcePhase.cpp).
  if (!setup_.loads.heat_flux.empty()) add_heat_flux_heating(t, step);
  // 13. G2P, FLIP: v_p += dt sum a_g S, x_p += dt sum v*_g S (Alg. 14, eq. 1.76).
  {
    PhaseTimers::Scope timer(phase_timers(), "MPM: interpolate to particles and update");
    for (MpmMaterial& m : mats) {
      Particles& p = m.particles;
      // v_n, needed only to clamp rogue speeds (<maximum_particle_velocity> given).
      const std::vector<Vec3> v_old = setup_.flags.maximum_particle_velocity < 3e105 ? p.v : std::vector<Vec3>{};
      const std::vector<Vec3> v_ledger = ledger ? p.v : std::vector<Vec3>{};  // v_n (mpm/EnergyLedger.h)
      grid_to_particles(m.stencils, m.grid, dt, p);
      if (ledger) ledger_sink.transfer_loss -= particle_increment_energy(p, v_ledger);
      wrap_periodic_positions(setup_.grid, p);  // re-enter through the opposite periodic face
      update_temperatures(m, dt);  // T += dt (sum rate_g S + model heating)
      if (contact && !contact_nodes_.friction_work.empty())  // T += sum S W_g/(c_v m_g) (FrictionHeating.h)
        friction_heat_to_particles(m.stencils, m.grid, contact_nodes_.friction_work[std::size_t(&m - mats.data())],
                                   m.specific_heat, p);
      if (setup_.flags.test_for_negative_temperatures) check_temperatures(m, step);  // T < 0: exit 4
      // The lowest particle with a non-finite velocity or more than one cell
      // beyond a (non-periodic) domain face (threads), then its message: within
      // the CFL limit a particle moves less than a cell per step, so that is a
      // blow-up. A particle less than a cell beyond a face has left the domain
      // and is deleted below (Uintah's relocation rule, mpm/ParticleDeletion.h).
      const Grid& domain = setup_.grid;
      auto fine = [&](std::size_t i) {
        if (!p.v[i].allFinite()) return false;
        for (int d = 0; d < 3; ++d) {
          if (domain.periodic[d]) continue;
          const double x = p.x[i][d];
          if (!(x > domain.lower[d] - domain.dx[d] && x < domain.upper[d] + domain.dx[d])) return false;
        }
        return true;
      };
      const long np = static_cast<long>(p.size());
      long bad = np;
#pragma omp parallel for schedule(static) reduction(min : bad) if (np >= 4096)
      for (long i = 0; i < np; ++i)
        if (!fine(std::size_t(i))) bad = std::min(bad, i);
      if (bad < np)
        fail_particle(m, std::size_t(bad), step, "interpolate to particles",
                      p.v[bad].allFinite() ? "particle left the grid (more than one cell beyond a domain face in one step)"
                                           : "non-finite velocity");
      delete_particles(m, v_old.empty() ? p.v : v_old, step);  // Vaango's limits (mpm/ParticleDeletion.h)
    }
  }
  if (ledger && layout_.distributed) {  // the step's ledger terms over the ranks, in rank order
    ledger_.contact_removed += sum_over_ranks(ledger_step.contact_removed);
    ledger_.boundary_removed += sum_over_ranks(ledger_step.boundary_removed);
    ledger_.grid_force_work += sum_over_ranks(ledger_step.grid_force_work);
    ledger_.transfer_loss += sum_over_ranks(ledger_step.transfer_loss);
  }
  // On MPI ranks: particles that entered another rank's patch move there (mpm/MpmRanks.cpp).
  migrate_particles();
  time_ = t + dt;
}

double MpmComponent::mms_displacement_error() const {
  double e2 = 0.0;
  for (const MpmMaterial& m : setup_.materials)
    if (m.mms) {  // per material: sqrt(sum V0 |u - u*|^2 / sum V0), both sums over the MPI ranks
      const auto [num, den] = mms_displacement_error_sums(*m.mms, m.particles, time_);
      const double n = sum_over_ranks(num), d = sum_over_ranks(den);
      e2 += std::pow(d > 0.0 ? std::sqrt(n / d) : 0.0, 2);
    }
  return std::sqrt(e2);
}

std::vector<std::string> mpm_interpolators() {
  return {"linear", "gimp", "cpdi", "cpti", "3rdorderBS", "4thorderBS", "cpgimp"};
}
std::vector<std::string> mpm_contact_types() { return contact_types(); }

}  // namespace tephra
