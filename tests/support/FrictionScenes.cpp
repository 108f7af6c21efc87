#include "tests/support/FrictionScenes.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"

namespace tephra {

namespace {

std::string box_material(double density, double K, double G, double x0, double x1, double z0, double z1,
                         double y1, double u0) {
  std::ostringstream s;
  s.precision(17);
  s << "<material><density>" << density << "</density><constitutive_model type='comp_neo_hook'><bulk_modulus>" << K
    << "</bulk_modulus><shear_modulus>" << G << "</shear_modulus></constitutive_model>"
    << "<thermal_conductivity>1</thermal_conductivity><specific_heat>1</specific_heat>"
    << "<geom_object><box><min>[" << x0 << ",0," << z0 << "]</min><max>[" << x1 << "," << y1 << "," << z1
    << "]</max></box><res>[2,2,2]</res><velocity>[" << u0 << ",0,0]</velocity><temperature>300</temperature>"
    << "</geom_object></material>";
  return s.str();
}

}  // namespace

double FrictionRun::slope(double t_from) const {
  double n = 0, st = 0, su = 0, stt = 0, stu = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] < t_from) continue;
    n += 1, st += t[i], su += u[i], stt += t[i] * t[i], stu += t[i] * u[i];
  }
  return (n * stu - st * su) / (n * stt - st * st);
}

FrictionRun run_friction_scene(const FrictionScene& sc) {
  const double H = 0.025, h = H / sc.refine, g = kFrictionSceneG;
  const double x0 = sc.u0 > 0.0 ? 0.05 : 0.1;  // room to slide 0.05 m (u0 T) either way
  std::ostringstream deck;
  deck.precision(17);
  deck << "<Uintah_specification><MPM><time_integrator>explicit</time_integrator><interpolator>"
       << sc.interpolator << "</interpolator>"
       << (sc.heating ? "<do_contact_friction_heating>true</do_contact_friction_heating>" : "") << "</MPM>"
       << "<PhysicalConstants><gravity>[" << g * std::sin(sc.theta) << ",0," << -g * std::cos(sc.theta)
       << "]</gravity></PhysicalConstants><MaterialProperties><MPM>"
       << box_material(1e4, 1e8, 5e7, 0.0, 0.4, 0.0, H, h, 0.0)
       << box_material(1e3, 1e7, 5e6, x0, x0 + 0.1, H, 3 * H, h, sc.u0) << "<contact><type>" << sc.contact
       << "</type><mu>" << sc.mu << "</mu><materials>[0,1]</materials></contact></MPM></MaterialProperties>"
       << "<Grid><BoundaryConditions>"
       << "<Face side='z-'><BCType id='0' var='Dirichlet' label='Velocity'><value>[0,0,0]</value></BCType></Face>"
       << "<Face side='y-'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
       << "<Face side='y+'><BCType id='all' var='symmetry' label='Symmetric'></BCType></Face>"
       << "</BoundaryConditions><Level><Box><lower>[0,0,0]</lower><upper>[0.4," << h << "," << 4 * H
       << "]</upper><resolution>[" << 16 * sc.refine << ",1," << 4 * sc.refine
       << "]</resolution><extraCells>[" << sc.extra_cells << "," << sc.extra_cells << "," << sc.extra_cells
       << "]</extraCells><patches>[1,1,1]</patches></Box></Level></Grid>"
       << "</Uintah_specification>";
  auto parsed = load_deck_from_string(deck.str(), "friction_scene.ups", ".");
  auto c = make_mpm_component(*parsed);
  c->initialize();
  auto thermal = [&] {
    double e = 0;
    for (const MpmMaterial& m : c->materials())
      for (std::size_t i = 0; i < m.particles.size(); ++i)
        e += m.particles.mass[i] * m.specific_heat * m.particles.temperature[i];
    return e;
  };
  struct Block {
    double m = 0, x = 0, ke = 0;
    double u = 0, w = 0;
  };
  auto block = [&] {
    const Particles& p = c->materials()[1].particles;
    Block b;
    for (std::size_t i = 0; i < p.size(); ++i) {
      b.m += p.mass[i];
      b.x += p.mass[i] * p.x[i][0];
      b.u += p.mass[i] * p.v[i][0];
      b.w += p.mass[i] * p.v[i][2];
      b.ke += 0.5 * p.mass[i] * p.v[i].squaredNorm();
    }
    b.x /= b.m, b.u /= b.m, b.w /= b.m;
    return b;
  };
  const double E0 = thermal();
  const Block b0 = block();
  FrictionRun r;
  r.mass = b0.m;
  double t = 0;
  int step = 0;
  while (t < sc.end_time - 1e-15) {
    const double dt = std::min(0.4 * c->stable_timestep(), sc.end_time - t);
    c->advance(t, dt, ++step);
    t += dt;
    const Block b = block();
    r.t.push_back(t), r.u.push_back(b.u), r.w.push_back(b.w);
  }
  const Block b1 = block();
  r.distance = b1.x - b0.x;
  r.ke_lost = b0.ke - b1.ke;
  r.heat = thermal() - E0;
  return r;
}

}  // namespace tephra
