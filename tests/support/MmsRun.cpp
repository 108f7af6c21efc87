#include "tests/support/MmsRun.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include <Eigen/LU>

#include "core/deck/DeckLoader.h"
#include "core/deck/DeckNode.h"
#include "mpm/MpmComponent.h"
#include "mpm/mms/ManufacturedSolution.h"
#include "models/solid/CnhMms.h"
#include "tests/support/TestPaths.h"

namespace tephra::test {

namespace {
DeckNode& child(DeckNode& n, const std::string& name) {
  for (DeckNode& c : n.children)
    if (c.name == name) return c;
  throw std::runtime_error("the MMS deck has no <" + name + "> under <" + n.name + ">");
}

// The rms displacement error of AxisAligned by component (x, y, z) over the
// particles of three regions of their reference position X in the unit cube:
// the band within 2 cells of a face (the symmetry planes), the interior (2
// cells or more from every face), and the core (0.25 m or more from every
// face: a signal from a face, at c = 100 m/s, reaches it after 0.0025 s); and
// for component i the band within 2 cells of the two faces normal to e_i
// (where u_i is odd) against the rest. Printed on one line.
void print_region_errors(const MpmComponent& comp, int cells, double t) {
  const auto& m = comp.materials()[0];
  double num[3][5] = {}, cnt[3][5] = {};
  for (std::size_t i = 0; i < m.particles.size(); ++i) {
    const Vec3 X = m.particles.x[i] - m.particles.displacement[i];
    const Vec3 e = m.particles.displacement[i] - m.mms->displacement(X, t);
    const double dist = std::min(X.minCoeff(), 1.0 - X.maxCoeff());
    const int region = dist * cells < 2 ? 0 : 1;
    for (int c = 0; c < 3; ++c) {
      const double e2 = e[c] * e[c];
      num[c][region] += e2, cnt[c][region] += 1;
      if (dist >= 0.25) num[c][2] += e2, cnt[c][2] += 1;
      const int normal = std::min(X[c], 1.0 - X[c]) * cells < 2 ? 3 : 4;
      num[c][normal] += e2, cnt[c][normal] += 1;
    }
  }
  std::printf("  t %.5f", t);
  for (int c = 0; c < 3; ++c) {
    std::printf("  u%c band/int/core/nband/nrest", "xyz"[c]);
    for (int r = 0; r < 5; ++r) std::printf(" %.4e", cnt[c][r] > 0 ? std::sqrt(num[c][r] / cnt[c][r]) : 0.0);
  }
  std::printf("\n");
  std::fflush(stdout);
}

// The conforming seeding of MmsRunOptions::conforming_ring (quarter ring
// about the z axis in x, y >= 0; plane strain, one particle across z).
// The material's seeded particles are replaced; the MMS initial state at
// t = 0 is set as MpmComponent::initialize does (x = X + u(X,0), v, F, V),
// and the per-particle state the first stress update made (wave speed, zero
// stress at F(X,0) = I for ExpandingRing) is taken from the first seeded
// particle. The returned count is the new number of particles.
long seed_conforming_quarter_ring(MpmMaterial& m, double inner, double outer, int ppc) {
  const Particles old = m.particles;
  if (old.size() == 0) throw std::runtime_error("conforming_ring: the deck seeded no particles");
  const Vec3 h = m.grid.h;
  const double delta = h[0] / ppc, pi = std::acos(-1.0);
  const int layers = int(std::lround((outer - inner) / delta));
  const double dR = (outer - inner) / layers, hz = h[2], z = old.x[0][2];
  Particles p;
  long long id = 0;
  for (int i = 0; i < layers; ++i) {
    const double R = inner + (i + 0.5) * dR;
    const int sectors = std::max(1, int(std::lround(0.5 * pi * R / delta)));
    const double dtheta = 0.5 * pi / sectors;
    for (int j = 0; j < sectors; ++j) {
      const double theta = (j + 0.5) * dtheta, c = std::cos(theta), s = std::sin(theta);
      const double V = R * dR * dtheta * hz;  // the annular sector's volume
      Mat3 size = Mat3::Zero();                // columns: dR e_R, R dtheta e_theta, h_z e_z in cell units
      size.col(0) = Vec3(dR * c / h[0], dR * s / h[1], 0.0);
      size.col(1) = Vec3(-R * dtheta * s / h[0], R * dtheta * c / h[1], 0.0);
      size(2, 2) = hz / h[2];
      p.add(Vec3(R * c, R * s, z), Vec3::Zero(), m.density * V, V, old.temperature[0], old.color[0], id++, size);
    }
  }
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec3 X = p.x[k];
    const Vec3 u = m.mms->displacement(X, 0.0);
    p.x[k] = X + u;
    p.displacement[k] = u;
    p.v[k] = m.mms->velocity(X, 0.0);
    p.F[k] = m.mms->deformation_gradient(X, 0.0);
    p.volume[k] = p.F[k].determinant() * p.volume0[k];
    p.stress[k] = old.stress[0];
    p.wave_speed[k] = old.wave_speed[0];
    p.energy_density[k] = old.energy_density[0];
  }
  // The model's history columns: each particle takes the first seeded particle's values.
  for (std::size_t c = 0; c < old.history.size(); ++c) {
    const std::size_t width = old.history[c].size() / old.size();
    std::vector<double> column;
    for (std::size_t k = 0; k < p.size(); ++k)
      column.insert(column.end(), old.history[c].begin(), old.history[c].begin() + long(width));
    p.history.push_back(std::move(column));
  }
  m.particles = std::move(p);
  m.F_old = m.particles.F;
  m.L.assign(m.particles.size(), Mat3::Zero());
  return long(m.particles.size());
}

}  // namespace

MmsRunResult run_axis_aligned(const MmsRunOptions& o) {
  const std::string& interpolator = o.interpolator;
  const int cells = o.cells, particles_per_cell_dir = o.particles_per_cell_dir;
  const double end_time = o.end_time;
  auto deck = load_deck(o.deck.empty() ? shared_dir() + "/decks/inputs/MPM/AA.ups" : o.deck);
  DeckNode& root = deck->root;
  child(child(root, "MPM"), "interpolator").text = interpolator;
  DeckNode& box = child(child(child(root, "Grid"), "Level"), "Box");
  const std::string c = std::to_string(cells);
  child(box, "resolution").text = "[" + c + "," + c + "," + (o.planar ? std::string("1") : c) + "]";
  if (o.planar && o.cubic_z) {
    const Vec3 lo = box.get_vec3("lower"), up = box.get_vec3("upper");
    char text[128];
    std::snprintf(text, sizeof text, "[%.17g,%.17g,%.17g]", up[0], up[1], lo[2] + (up[0] - lo[0]) / cells);
    child(box, "upper").text = text;
  }
  DeckNode& mat = child(child(child(root, "MaterialProperties"), "MPM"), "material");
  if (o.periodic_mirror) {
    const std::string c2 = std::to_string(2 * cells);
    child(box, "resolution").text = "[" + c2 + "," + c2 + "," + c2 + "]";
    child(box, "lower").text = "[-1,-1,-1]";
    child(box, "extraCells").text = "[0,0,0]";
    DeckNode& level = child(child(root, "Grid"), "Level");
    DeckNode per = child(box, "extraCells");
    per.name = "periodic";
    per.text = "[1,1,1]";
    per.children.clear();
    level.children.push_back(per);
    DeckNode& grid = child(root, "Grid");
    grid.children.erase(std::remove_if(grid.children.begin(), grid.children.end(),
                                       [](const DeckNode& n) { return n.name == "BoundaryConditions"; }),
                        grid.children.end());
    DeckNode& block = child(child(mat, "geom_object"), "box");
    child(block, "min").text = "[-1,-1,-1]";
  }
  const std::string r = std::to_string(particles_per_cell_dir);
  child(child(mat, "geom_object"), "res").text = "[" + r + "," + r + "," + (o.planar ? std::string("1") : r) + "]";
  const DeckNode& time = root.require_child("Time");
  const double multiplier =
      o.timestep_multiplier > 0.0 ? o.timestep_multiplier : time.get_double("timestep_multiplier");
  const double delt_max = time.get_double("delt_max");

  const auto start = std::chrono::steady_clock::now();
  auto comp = make_mpm_component(*deck);
  if (o.amplitude > 0.0) {  // before initialize(): the start state and the deformed size use it
    MpmMaterial& m = comp->materials()[0];
    const auto* cnh = dynamic_cast<const CnhMms*>(m.model.get());
    if (!cnh || !m.mms || m.mms->name() != "AxisAligned")
      throw std::runtime_error("MmsRunOptions::amplitude: AxisAligned with cnh_mms only");
    m.mms = make_axis_aligned_mms(cnh->params(), m.density, o.amplitude);
  }
  comp->initialize();
  MmsRunResult out;
  if (o.conforming_ring)
    seed_conforming_quarter_ring(comp->materials()[0], o.ring_inner, o.ring_outer, particles_per_cell_dir);
  out.particles = long(comp->materials()[0].particles.size());
  for (double v : comp->materials()[0].particles.volume0) out.volume0 += v;
  double t = 0.0;
  // TEPHRA_MMS_REGIONS=1: the error by component and region at t >= end/8, end/4, end/2, end.
  const bool regions = std::getenv("TEPHRA_MMS_REGIONS") != nullptr;
  int checkpoint = 0;
  const double checkpoints[4] = {end_time / 8, end_time / 4, end_time / 2, end_time};
  while (t < end_time * (1 - 1e-12)) {
    // end_on_max_time_exactly: the last step lands on end_time.
    const double dt = std::min({multiplier * comp->stable_timestep(), delt_max, end_time - t});
    comp->advance(t, dt, ++out.steps);
    t += dt;
    if (regions && checkpoint < 4 && t >= checkpoints[checkpoint] * (1 - 1e-12)) {
      print_region_errors(*comp, cells, t);
      ++checkpoint;
    }
  }
  out.error = comp->mms_displacement_error();
  if (o.keep_particle_errors) {
    const auto& m = comp->materials()[0];
    out.particle_errors.assign(m.particles.size(), Vec3::Zero());
    out.particle_X.assign(m.particles.size(), Vec3::Zero());
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
      const std::size_t id = std::size_t(m.particles.id[i]);
      if (id >= m.particles.size()) throw std::runtime_error("keep_particle_errors: particle ids are not 0..n-1");
      const Vec3 X = m.particles.x[i] - m.particles.displacement[i];
      out.particle_errors[id] = m.particles.displacement[i] - m.mms->displacement(X, t);
      out.particle_X[id] = X;
    }
  }
  if (std::getenv("TEPHRA_MMS_BANDS")) {
    const auto& m = comp->materials()[0];
    double num[4] = {0, 0, 0, 0}, cnt[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
      const Vec3 X = m.particles.x[i] - m.particles.displacement[i];
      const double dist = std::min(X.minCoeff(), 1.0 - X.maxCoeff()) * cells;  // cells to nearest face
      const int b = dist < 1 ? 0 : dist < 2 ? 1 : dist < 3 ? 2 : 3;
      num[b] += (m.particles.displacement[i] - m.mms->displacement(X, t)).squaredNorm();
      cnt[b] += 1;
    }
    for (int b = 0; b < 4; ++b) std::printf("  band %d: rms %.3e (n %g)\n", b, std::sqrt(num[b] / cnt[b]), cnt[b]);
  }
  if (o.ring_outer > 0.0) {
    const auto& m = comp->materials()[0];
    const double h = comp->materials()[0].grid.h[0];
    double num[4] = {0, 0, 0, 0};
    for (std::size_t i = 0; i < m.particles.size(); ++i) {
      const Vec3 X = m.particles.x[i] - m.particles.displacement[i];
      const double R = std::hypot(X[0], X[1]);
      const double dist = std::min(R - o.ring_inner, o.ring_outer - R) / h;  // cells to the nearest curved face
      const int b = dist < 1 ? 0 : dist < 2 ? 1 : dist < 3 ? 2 : 3;
      num[b] += m.particles.volume0[i] * (m.particles.displacement[i] - m.mms->displacement(X, t)).squaredNorm();
      out.band_rms[b] += m.particles.volume0[i];
      ++out.band_count[b];
    }
    for (int b = 0; b < 4; ++b) out.band_rms[b] = out.band_rms[b] > 0 ? std::sqrt(num[b] / out.band_rms[b]) : 0.0;
    if (std::getenv("TEPHRA_RING_THETA")) {  // rms radial / hoop error by angle from the x axis (6 bands of 15 deg)
      double er[6] = {}, et[6] = {}, vol[6] = {};
      for (std::size_t i = 0; i < m.particles.size(); ++i) {
        const Vec3 X = m.particles.x[i] - m.particles.displacement[i];
        const double th = std::atan2(X[1], X[0]);
        const int b = std::min(5, std::max(0, int(th / (std::acos(-1.0) / 12))));
        const Vec3 e = m.particles.displacement[i] - m.mms->displacement(X, t);
        const Vec3 er_dir(std::cos(th), std::sin(th), 0.0), et_dir(-std::sin(th), std::cos(th), 0.0);
        er[b] += m.particles.volume0[i] * std::pow(e.dot(er_dir), 2);
        et[b] += m.particles.volume0[i] * std::pow(e.dot(et_dir), 2);
        vol[b] += m.particles.volume0[i];
      }
      for (int b = 0; b < 6; ++b)
        std::printf("    theta [%2d,%2d) deg: rms radial %.4e hoop %.4e\n", 15 * b, 15 * b + 15, std::sqrt(er[b] / vol[b]),
                    std::sqrt(et[b] / vol[b]));
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace tephra::test
