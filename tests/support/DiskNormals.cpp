#include "tests/support/DiskNormals.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "mpm/contact/ContactNormals.h"

namespace tephra {

DiskNormalError disk_normal_error(int cells, int res, const std::string& interpolator) {
  const double R = 0.25, L = 1.0, h = L / cells;
  const double pi = std::acos(-1.0);
  std::ostringstream disk, block, s;
  disk.precision(17);
  disk << "<cylinder><bottom>[0.5,0.5,0]</bottom><top>[0.5,0.5," << h << "]</top><radius>" << R
       << "</radius></cylinder>";
  block.precision(17);
  block << "<difference><box><min>[0,0,0]</min><max>[" << L << "," << L << "," << h << "]</max></box>" << disk.str()
        << "</difference>";
  auto material = [&](const std::string& geometry) {
    std::ostringstream m;
    m << "<material><density>1000</density><constitutive_model type='comp_neo_hook'><bulk_modulus>1e7"
      << "</bulk_modulus><shear_modulus>5e6</shear_modulus></constitutive_model>"
      << "<thermal_conductivity>0</thermal_conductivity><specific_heat>1</specific_heat><geom_object>" << geometry
      << "<res>[" << res << "," << res << ",2]</res><velocity>[0,0,0]</velocity><temperature>300</temperature>"
      << "</geom_object></material>";
    return m.str();
  };
  s.precision(17);
  s << "<Uintah_specification><MPM><time_integrator>explicit</time_integrator><interpolator>" << interpolator
    << "</interpolator></MPM><PhysicalConstants><gravity>[0,0,0]</gravity></PhysicalConstants>"
    << "<MaterialProperties><MPM>" << material(disk.str()) << material(block.str())
    << "<contact><type>single_velocity</type></contact></MPM></MaterialProperties><Grid><BoundaryConditions>"
    << "<Face side='z-'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
    << "<Face side='z+'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
    << "</BoundaryConditions><Level><Box><lower>[0,0,0]</lower><upper>[" << L << "," << L << "," << h
    << "]</upper><resolution>[" << cells << "," << cells << ",1]</resolution><extraCells>[0,0,0]</extraCells>"
    << "<patches>[1,1,1]</patches></Box></Level></Grid></Uintah_specification>";
  auto deck = load_deck_from_string(s.str(), "disk_normals.ups", ".");
  auto c = make_mpm_component(*deck);
  c->initialize();
  c->advance(0.0, 1e-12, 1);
  std::vector<std::vector<Vec3>> g;
  std::vector<const NodeGrid*> grids;
  for (const MpmMaterial& m : c->materials()) {
    g.emplace_back();
    mass_gradient(m.particles, m.stencils, m.grid, g.back());
    grids.push_back(&m.grid);
  }
  collinear_normals(grids, g);
  const NodeGrid& grid = *grids[0];
  constexpr int kSectors = 16;
  std::array<Vec3, kSectors> sum_n, sum_r;
  std::array<double, kSectors> sum_w{};
  sum_n.fill(Vec3::Zero());
  sum_r.fill(Vec3::Zero());
  DiskNormalError e;
  double weight = 0.0;
  // The node plane z = 0 (the z = h plane holds the same values).
  for (int j = 0; j < grid.n[1]; ++j)
    for (int i = 0; i < grid.n[0]; ++i) {
      const std::size_t node = grid.index(IntVec3(i, j, 0));
      const double md = grid.mass[node], mb = grids[1]->mass[node];
      if (!(md > 0.0 && mb > 0.0)) continue;
      Vec3 radial = grid.position(i, j, 0) - Vec3(0.5, 0.5, 0.0);
      radial[2] = 0.0;
      radial.normalize();
      Vec3 normal = g[0][node];
      normal[2] = 0.0;  // the in-plane part (both bodies also end at the z node planes)
      normal.normalize();
      const double angle = std::acos(std::min(1.0, normal.dot(radial)));
      const double w = std::min(md, mb);
      e.largest = std::max(e.largest, angle);
      e.mean += w * angle;
      weight += w;
      ++e.nodes;
      const double phi = std::atan2(radial[1], radial[0]) + pi;  // [0, 2 pi]
      const int k = std::min(kSectors - 1, int(phi / (2 * pi) * kSectors));
      sum_n[k] += w * normal, sum_r[k] += w * radial, sum_w[k] += w;
    }
  e.mean /= weight;
  double total = 0.0;
  for (int k = 0; k < kSectors; ++k) {
    if (!(sum_w[k] > 0.0)) continue;
    e.arc_mean += sum_w[k] * std::acos(std::min(1.0, sum_n[k].normalized().dot(sum_r[k].normalized())));
    total += sum_w[k];
  }
  e.arc_mean /= total;
  return e;
}

}  // namespace tephra
