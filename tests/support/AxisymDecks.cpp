#include "tests/support/AxisymDecks.h"

#include <sstream>

namespace tephra::test {

namespace {

std::string vec(double a, double b, double c) {
  std::ostringstream o;
  o.precision(17);
  o << "[" << a << "," << b << "," << c << "]";
  return o.str();
}

std::string face(const char* side, const std::string& kind) {
  std::ostringstream o;
  o << "<Face side=\"" << side << "\">";
  if (kind == "Symmetric") {
    o << "<BCType id=\"all\" label=\"Symmetric\" var=\"symmetry\"/>";
  } else {
    o << "<BCType id=\"0\" label=\"Pressure\" var=\"Neumann\"><value>0</value></BCType>"
      << "<BCType id=\"0\" label=\"Velocity\" var=\"Neumann\"><value>[0,0,0]</value></BCType>"
      << "<BCType id=\"0\" label=\"Temperature\" var=\"Neumann\"><value>0</value></BCType>"
      << "<BCType id=\"0\" label=\"Density\" var=\"Neumann\"><value>0</value></BCType>"
      << "<BCType id=\"0\" label=\"SpecificVol\" var=\"computeFromDensity\"><value>0</value></BCType>";
  }
  o << "</Face>";
  return o.str();
}

std::string state(double rho, double temp, double ur, double uz) {
  std::ostringstream o;
  o.precision(17);
  o << "<res>[2,2,1]</res><velocity>" << vec(ur, uz, 0) << "</velocity><temperature>" << temp
    << "</temperature><density>" << rho << "</density><pressure>" << rho * 0.4 * 717.5 * temp << "</pressure>";
  return o.str();
}

}  // namespace

std::string axisym_deck_text(const AxisymDeck& d) {
  const double dr = (d.r_hi - d.r_lo) / d.nr;
  std::ostringstream o;
  o.precision(17);
  o << "<Uintah_specification><Meta><title>axisymmetric ICE test</title></Meta>"
    << "<SimulationComponent type=\"ice\"/>"
    << "<Time><maxTime>" << d.max_time << "</maxTime><initTime>0</initTime><delt_min>0</delt_min>"
    << "<delt_max>1</delt_max><delt_init>1e-7</delt_init><timestep_multiplier>1</timestep_multiplier>"
    << "<end_on_max_time_exactly>true</end_on_max_time_exactly></Time>";
  if (d.axisymmetric) o << "<MPM><axisymmetric>true</axisymmetric></MPM>";
  o << "<Grid><BoundaryConditions>" << face("x-", d.x_minus) << face("x+", d.x_plus);
  if (!d.periodic_z) o << face("y-", "Symmetric") << face("y+", "Symmetric");
  o << face("z-", "Symmetric") << face("z+", "Symmetric") << "</BoundaryConditions>"
    << "<Level><Box label=\"1\"><lower>" << vec(d.r_lo, 0, 0) << "</lower><upper>" << vec(d.r_hi, d.z_hi, dr)
    << "</upper><extraCells>" << (d.periodic_z ? "[1,0,1]" : "[1,1,1]") << "</extraCells><patches>[1,1,1]</patches>"
    << "<resolution>[" << d.nr << "," << d.nz << ",1]</resolution></Box>";
  if (d.periodic_z) o << "<periodic>[0,1,0]</periodic>";
  o << "</Level></Grid>"
    << "<DataArchiver><filebase>axisym.uda</filebase><outputInterval>1</outputInterval></DataArchiver>"
    << "<CFD><cfl>" << d.cfl << "</cfl><ICE><advection type=\"" << d.advection << "\"/></ICE></CFD>"
    << "<PhysicalConstants><gravity>[0,0,0]</gravity><reference_pressure>101325</reference_pressure></PhysicalConstants>"
    << "<MaterialProperties><ICE><material><EOS type=\"ideal_gas\"/><dynamic_viscosity>0</dynamic_viscosity>"
    << "<thermal_conductivity>0</thermal_conductivity><specific_heat>717.5</specific_heat><gamma>1.4</gamma>";
  const std::string inner_box = "<box label=\"inner\"><min>" + vec(-1, -1, -1) + "</min><max>" +
                                vec(d.x_split, d.y_split, 1e9) + "</max></box>";
  if (d.inner) {
    o << "<geom_object><difference><box label=\"all\"><min>" << vec(-1, -1, -1) << "</min><max>"
      << vec(1e9, 1e9, 1e9) << "</max></box>" << inner_box << "</difference>"
      << state(d.rho, d.temp, d.u_r, d.u_z) << "</geom_object>"
      << "<geom_object><box label=\"inner\"/>" << state(d.rho_in, d.temp_in, d.u_r, d.u_z_in) << "</geom_object>";
  } else {
    o << "<geom_object><box label=\"all\"><min>" << vec(-1, -1, -1) << "</min><max>" << vec(1e9, 1e9, 1e9)
      << "</max></box>" << state(d.rho, d.temp, d.u_r, d.u_z) << "</geom_object>";
  }
  o << "</material></ICE></MaterialProperties></Uintah_specification>";
  return o.str();
}

}  // namespace tephra::test
