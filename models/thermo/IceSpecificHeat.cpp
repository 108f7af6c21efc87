#include "models/thermo/IceSpecificHeat.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace tephra {
namespace {

// Polynomial (Uintah PolynomialCv): "Cv(T) = SUM(a_i x^i)/x^m from i=0 to m",
// T clamped to [Tmin, Tmax] (defaults 0 and 1e6). Uintah's getSpecificHeat
// returns x^m / SUM (the reciprocal of its own formula): for the EOSData
// product files (a_7 ~ 1.5e3) that gives c_v ~ 7e-4 J/(kg K). Tephra follows
// the documented formula, which tends to a_m (~1.5 kJ/(kg K), the product-gas
// value) at high T. Horner in 1/T: c_v = a_m + a_{m-1}/T + ... + a_0/T^m.
class PolynomialCv final : public IceSpecificHeat {
 public:
  PolynomialCv(std::vector<double> a, double Tmin, double Tmax) : a_(std::move(a)), Tmin_(Tmin), Tmax_(Tmax) {}
  const char* type() const override { return "Polynomial"; }
  double cv(double T) const override {
    const double inv = 1.0 / std::clamp(T, Tmin_, Tmax_);
    double s = 0;
    for (double ai : a_) s = s * inv + ai;  // a_0 first: ends with a_m
    return s;
  }

 private:
  std::vector<double> a_;
  double Tmin_, Tmax_;
};

// Debye (Uintah DebyeCv): c_v = 9 N k_B (T/T_D)^3 int_0^{T_D/T} x^4 e^x/(e^x-1)^2 dx,
// k_B = 1.3806503e-23 J/K (the value Uintah uses), N = <Atoms>. Limits: 3 N k_B
// (Dulong-Petit) for T >> T_D, (12 pi^4/5) N k_B (T/T_D)^3 for T << T_D.
// Uintah uses a 1000-term Riemann sum; here composite Simpson with 2000
// intervals (the integrand is smooth, ~x^2 at 0): relative error < 1e-12.
class DebyeCv final : public IceSpecificHeat {
 public:
  DebyeCv(int atoms, double TD) : N_(atoms), TD_(TD) {}
  const char* type() const override { return "Debye"; }
  double cv(double T) const override {
    const double xD = TD_ / T;
    // x^4 e^x/(e^x-1)^2 = x^4 e^-x/(1-e^-x)^2, written with expm1 (no overflow, no cancellation).
    auto f = [](double x) {
      if (x <= 0) return 0.0;
      const double d = -std::expm1(-x);
      return x * x * x * x * std::exp(-x) / (d * d);
    };
    constexpr int n = 2000;
    const double h = xD / n;
    double s = f(0) + f(xD);
    for (int i = 1; i < n; ++i) s += (i % 2 ? 4.0 : 2.0) * f(i * h);
    const double integral = s * h / 3.0;
    constexpr double kB = 1.3806503e-23;
    return 9.0 * N_ * kB * integral / (xD * xD * xD);
  }

 private:
  int N_;
  double TD_;
};

// Component (Uintah ComponentCv): molar c_p/R of each gas from the two-range
// polynomial fits in Heywood, Internal Combustion Engine Fundamentals (1988)
// p. 131 (T in K, clamped to [300, 5000], low range T <= 1000), mixed by mole
// fraction X; gamma_mix = 1.6 (O, H) / 1.4 (diatomic) / 1.3 (CO2, H2O) mixed by X;
// c_v = 1000 R (c_p/R)/gamma_mix / M_mix, R = 8.3144621 J/(mol K), M in g/mol.
// Deliberate difference: Uintah uses 1.00794 g/mol for H2; Tephra 2.01588.
struct GasFit {
  double low[5], high[5];  // c_p/R = b0 + b1 T + b2 T^2 + b3 T^3 + b4 T^4
  double molar_mass;       // g/mol
  double gamma;
};
constexpr GasFit kGases[10] = {
    {{0.24008e1, 0.87351e-2, -0.66071e-5, 0.20022e-8, 0.63274e-15},
     {0.44608e1, 0.30982e-2, -0.12393e-5, 0.22741e-9, -0.15526e-13}, 44.01, 1.3},  // CO2
    {{0.40701e1, -0.11084e-2, 0.41521e-5, -0.29637e-8, 0.80702e-12},
     {0.27168e1, 0.29451e-2, -0.80224e-6, 0.10227e-9, -0.48472e-14}, 18.01528, 1.3},  // H2O
    {{0.37101e1, -0.16191e-2, 0.36924e-5, -0.20320e-8, 0.23953e-12},
     {0.29841e1, 0.14891e-2, -0.57900e-6, 0.10365e-9, -0.69354e-14}, 28.01, 1.4},  // CO
    {{0.30574e1, 0.26765e-2, -0.58099e-5, 0.55210e-8, -0.18123e-11},
     {0.31002e1, 0.51119e-3, 0.52644e-7, -0.34910e-10, 0.36945e-14}, 2.01588, 1.4},  // H2
    {{0.36256e1, -0.18782e-2, 0.70555e-5, -0.67635e-8, 0.21556e-11},
     {0.36220e1, 0.73618e-3, -0.19652e-6, 0.36202e-10, -0.28946e-14}, 31.9988, 1.4},  // O2
    {{0.36748e1, -0.12082e-2, 0.23240e-5, -0.63218e-9, -0.22577e-12},
     {0.28963e1, 0.15155e-2, -0.57235e-6, 0.99807e-10, -0.65224e-14}, 28.0134, 1.4},  // N2
    {{0.29106e1, 0.95932e-3, -0.19442e-6, 0.13757e-10, 0.14225e-15},
     {0.29106e1, 0.95932e-3, -0.19442e-6, 0.13757e-10, 0.14225e-15}, 17.00734, 1.4},  // OH (one range)
    {{0.31890e1, 0.13382e-2, -0.52899e-6, 0.95919e-10, -0.64848e-14},
     {0.31890e1, 0.13382e-2, -0.52899e-6, 0.95919e-10, -0.64848e-14}, 30.0061, 1.4},  // NO (one range)
    {{0.25421e1, -0.27551e-4, -0.31028e-8, 0.45511e-11, -0.43681e-15},
     {0.25421e1, -0.27551e-4, -0.31028e-8, 0.45511e-11, -0.43681e-15}, 15.9994, 1.6},  // O (one range)
    {{2.5, 0, 0, 0, 0}, {2.5, 0, 0, 0, 0}, 1.00794, 1.6},  // H: c_p/R = 5/2 (monatomic ideal gas)
};
// Uintah writes 0.25 for H (c_p/R = 5/2 is the monatomic value; 0.25 looks like a typo).

class ComponentCv final : public IceSpecificHeat {
 public:
  explicit ComponentCv(const std::vector<double>& X) : X_(X) {
    for (int s = 0; s < 10; ++s) {
      gamma_ += X_[s] * kGases[s].gamma;
      molar_mass_ += X_[s] * kGases[s].molar_mass;
    }
  }
  const char* type() const override { return "Component"; }
  std::optional<double> gamma() const override { return gamma_; }
  double cv(double T) const override {
    const double t = std::clamp(T, 300.0, 5000.0);
    double cp_over_R = 0;
    for (int s = 0; s < 10; ++s) {
      const double* b = t <= 1000.0 ? kGases[s].low : kGases[s].high;
      cp_over_R += X_[s] * (b[0] + t * (b[1] + t * (b[2] + t * (b[3] + t * b[4]))));
    }
    constexpr double R = 8.3144621;
    return 1000.0 * R * cp_over_R / gamma_ / molar_mass_;
  }

 private:
  std::vector<double> X_;
  double gamma_ = 0, molar_mass_ = 0;
};

}  // namespace

IceSpecificHeatP make_polynomial_cv(int max_order, std::vector<double> a, double Tmin, double Tmax) {
  a.resize(static_cast<std::size_t>(max_order) + 1, 0.0);
  return std::make_shared<PolynomialCv>(std::move(a), Tmin, Tmax);
}

IceSpecificHeatP make_debye_cv(int atoms, double debye_temperature) {
  return std::make_shared<DebyeCv>(atoms, debye_temperature);
}

IceSpecificHeatP make_component_cv(const std::vector<double>& mole_fractions) {
  return std::make_shared<ComponentCv>(mole_fractions);
}

const std::vector<std::string>& component_cv_species() {
  static const std::vector<std::string> names = {"XCO2", "XH2O", "XCO", "XH2", "XO2",
                                                 "XN2",  "XOH",  "XNO", "XO",  "XH"};
  return names;
}

}  // namespace tephra
