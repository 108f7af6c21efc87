#include "tests/support/PrescribedDriver.h"

#include <cmath>
#include <fstream>
#include <sstream>

#include <unistd.h>

#include "core/deck/DeckLoader.h"
#include "mpm/MpmComponent.h"
#include "tests/support/TestPaths.h"

namespace tephra::test {

PrescribedHistory drive_prescribed(const std::string& model_xml, const std::vector<PrescribedRow>& rows,
                                   const PrescribedDriverOptions& options) {
  // The file, in Vaango's row format.
  // A folder per process and call (ctest runs test processes side by side).
  static int counter = 0;
  const std::string dir = scratch_dir("prescribed_driver_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
  const std::string file = dir + "/prescribed.txt";
  {
    std::ofstream out(file);
    out.precision(17);
    for (const PrescribedRow& r : rows) {
      out << r.t;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) out << ' ' << r.F(i, j);
      out << ' ' << r.angle_deg << ' ' << r.axis[0] << ' ' << r.axis[1] << ' ' << r.axis[2] << '\n';
    }
  }
  // A grid reaching past the deformed block: the block's corners are at most
  // sqrt(3) h from the origin, and F* maps them within max |F*| sqrt(3) h.
  const double h = 1e-3;
  PrescribedDeformation path;
  path.rows = rows;
  double reach = 1.0;
  for (const PrescribedRow& r : rows) reach = std::max(reach, path.at(r.t).norm());
  const int n = int(std::ceil(reach * std::sqrt(3.0))) + 2;
  std::ostringstream deck;
  deck.precision(17);
  deck << "<Uintah_specification><Meta><title>prescribed driver</title></Meta>"
       << "<SimulationComponent type=\"mpm\"/>"
       << "<Time><maxTime>" << rows.back().t << "</maxTime><initTime>" << rows.front().t
       << "</initTime><delt_min>0</delt_min><delt_max>1</delt_max><timestep_multiplier>1</timestep_multiplier></Time>"
       << "<DataArchiver><filebase>driver.uda</filebase><outputInterval>1</outputInterval>"
       << "<save label=\"StrainEnergy\"/><save label=\"AccStrainEnergy\"/>"
       << "<save label=\"PlasticWork\"/></DataArchiver>"
       << "<MPM><interpolator>linear</interpolator><use_prescribed_deformation>true</use_prescribed_deformation>"
       << "<prescribed_deformation_file>" << file << "</prescribed_deformation_file></MPM>"
       << "<PhysicalConstants><gravity>[0,0,0]</gravity></PhysicalConstants>"
       << "<MaterialProperties><MPM><material><density>" << options.density << "</density>" << options.material_xml
       << model_xml << "<geom_object><box label=\"cell\"><min>[0,0,0]</min><max>[" << h << "," << h << "," << h
       << "]</max></box><res>[2,2,2]</res><velocity>[0,0,0]</velocity><temperature>" << options.temperature
       << "</temperature></geom_object></material></MPM></MaterialProperties>"
       << "<Grid><Level><Box label=\"1\"><lower>[" << -n * h << "," << -n * h << "," << -n * h << "]</lower><upper>["
       << n * h << "," << n * h << "," << n * h << "]</upper><extraCells>[0,0,0]</extraCells><patches>[1,1,1]</patches>"
       << "</Box><spacing>[" << h << "," << h << "," << h << "]</spacing></Level></Grid></Uintah_specification>";
  auto d = load_deck_from_string(deck.str(), dir + "/driver.ups", dir);
  auto c = make_mpm_component(*d);
  c->initialize();

  PrescribedHistory out;
  auto sample = [&](double t) {
    const Particles& p = c->materials()[0].particles;
    out.time.push_back(t);
    out.F.push_back(p.F[0]);
    out.stress.push_back(p.stress[0]);
    std::vector<double> hist;
    for (const auto& column : p.history) {
      const std::size_t k = column.size() / p.size();
      hist.insert(hist.end(), column.begin(), column.begin() + long(k));
    }
    out.history.push_back(std::move(hist));
    const auto& work = c->materials()[0].plastic_work;
    out.plastic_work.push_back(work.empty() ? 0.0 : work[0]);
    const auto r = c->reductions({"StrainEnergy", "AccStrainEnergy", "PlasticWork"});
    out.strain_energy.push_back(r.at("StrainEnergy").at(0));
    out.acc_strain_energy.push_back(r.at("AccStrainEnergy").at(0));
    out.plastic_work_total.push_back(r.at("PlasticWork").at(0));
  };
  const double t0 = rows.front().t, t1 = rows.back().t;
  sample(t0);
  for (int s = 0; s < options.steps; ++s) {
    const double ta = t0 + (t1 - t0) * s / options.steps, tb = t0 + (t1 - t0) * (s + 1) / options.steps;
    c->advance(ta, tb - ta, s + 1);
    sample(tb);
  }
  return out;
}

}  // namespace tephra::test
