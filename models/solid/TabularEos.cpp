#include "models/solid/TabularEos.h"

#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include <Eigen/LU>

#include "models/JsonValue.h"
#include "models/ModelParameters.h"
#include "models/solid/PointLoop.h"

namespace tephra {

namespace {

const JsonValue& member(const JsonValue& object, const std::string& key, const std::string& where) {
  if (!object.is_object())
    throw JsonError(object.line, where + " must be an object, not " + json_kind_name(object.kind));
  const JsonValue* v = object.find(key);
  if (!v) throw JsonError(object.line, "no key \"" + key + "\" in " + where);
  return *v;
}

// "a, b" -> {"a", "b"} (Vaango splits the deck's variable lists at commas and trims).
std::vector<std::string> split_names(const std::string& text) {
  std::vector<std::string> out;
  std::stringstream ss(text);
  std::string item;
  while (std::getline(ss, item, ',')) {
    const auto b = item.find_first_not_of(" \t\r\n");
    const auto e = item.find_last_not_of(" \t\r\n");
    if (b != std::string::npos) out.push_back(item.substr(b, e - b + 1));
  }
  return out;
}

}  // namespace

PressureTable read_pressure_table(const std::string& json_text, const std::string& x_name,
                                  const std::string& p_name) {
  const JsonValue doc = parse_json(json_text);
  const JsonValue& contents = member(doc, "Vaango_tabular_data", "the document");
  const JsonValue& data = member(contents, "Data", "\"Vaango_tabular_data\"");
  const JsonValue& xv = member(data, x_name, "\"Data\"");
  const JsonValue& pv = member(data, p_name, "\"Data\"");
  const std::vector<double> x = xv.numbers("\"" + x_name + "\"");
  const std::vector<double> p = pv.numbers("\"" + p_name + "\"");
  if (x.size() < 2) throw JsonError(xv.line, "\"" + x_name + "\" needs at least two values (one segment)");
  if (p.size() != x.size())
    throw JsonError(pv.line, "\"" + p_name + "\" has " + std::to_string(p.size()) + " values, \"" + x_name +
                                 "\" has " + std::to_string(x.size()));
  for (std::size_t k = 0; k < x.size(); ++k) {
    if (!(x[k] > 0.0))
      throw JsonError(xv.array[k].line, "\"" + x_name + "\"[" + std::to_string(k) +
                                            "] must be > 0 (a density ratio rho/rho0)");
    if (k > 0 && !(x[k] > x[k - 1]))
      throw JsonError(xv.array[k].line, "\"" + x_name + "\" must increase strictly (index " + std::to_string(k) + ")");
    if (k > 0 && !(p[k] > p[k - 1]))
      throw JsonError(pv.array[k].line, "\"" + p_name + "\" must increase strictly with \"" + x_name + "\" (index " +
                                            std::to_string(k) +
                                            "): a positive bulk modulus on every segment (VT eq. 22.5)");
  }
  return PressureTable(x, p);
}

long TabularEos::update(const SolidUpdateInput& in, const SolidUpdateOutput& out) const {
  const Eigen::Matrix3d I = Eigen::Matrix3d::Identity();
  return for_each_point(in.F_new.size(), [&](std::size_t i) {
    const double J = in.F_new[i].determinant();
    if (!(J > 0.0) || !std::isfinite(J)) return false;
    const double eta = 1.0 / J;  // rho/rho0
    out.stress[i] = -table_.pressure(eta) * I;
    out.energy_density[i] = table_.energy(eta);
    out.wave_speed[i] = std::sqrt(table_.slope(eta) / in.density0);  // c^2 = dp/drho
    out.plastic_work[i] = 0.0;
    out.heating[i] = 0.0;
    return out.stress[i].allFinite();
  });
}

std::optional<SolidEosPoint> TabularEos::pressure_at_density(double rho, double density0, double) const {
  const double eta = rho / density0;
  SolidEosPoint e;
  e.pressure = table_.pressure(eta);
  e.dp_drho = table_.slope(eta) / density0;
  e.c2 = e.dp_drho;
  return e;
}

std::optional<double> TabularEos::density_at_pressure(double p_gauge, double density0, double) const {
  const double eta = table_.density_ratio(p_gauge);
  if (!(eta > 0.0)) return std::numeric_limits<double>::quiet_NaN();  // tension beyond any density
  return density0 * eta;
}

ConstitutiveModelP TabularEos::create(const ModelParameters& params) {
  const std::string text = params.get_string("filename", "");
  if (text.empty()) params.fail("filename", "tabular_eos needs <filename>: the JSON pressure table (VT §22.2)");
  const std::vector<std::string> x_names = split_names(params.get_string("independent_variables", ""));
  const std::vector<std::string> p_names = split_names(params.get_string("dependent_variables", ""));
  if (x_names.size() != 1)
    params.fail("independent_variables",
                "tabular_eos takes exactly one independent variable, the density ratio rho/rho0 (VT §22.2); got " +
                    std::to_string(x_names.size()));
  if (p_names.empty()) params.fail("dependent_variables", "tabular_eos needs one dependent variable, the pressure");
  if (p_names.size() > 1)
    params.missing_feature("dependent_variables",
                           "tabular_eos with more than one dependent variable (only the pressure has a role)");
  if (const ModelParameters* interp = params.block("interpolation")) {
    const std::string kind = interp->type_attribute();
    if (kind == "cubic") interp->missing_feature("type", "tabular_eos <interpolation type=\"cubic\">");
    if (kind != "linear") interp->fail("type", "interpolation type must be linear or cubic, not '" + kind + "'");
  }
  const std::string path = params.file_path("filename");
  std::ifstream file(path, std::ios::binary);
  if (!file)
    params.fail("filename", "cannot open the tabular_eos table '" + text +
                                "' (looked beside the deck, then in the working directory)");
  std::stringstream buffer;
  buffer << file.rdbuf();
  try {
    return std::make_shared<TabularEos>(read_pressure_table(buffer.str(), x_names[0], p_names[0]));
  } catch (const JsonError& e) {
    params.fail("filename", "tabular_eos table " + path + ":" + std::to_string(e.line()) + ": " + e.what());
  }
}

}  // namespace tephra
