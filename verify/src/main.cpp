// simpson-verify: the main job. For now it prints, in every precision, Φ_3 and its checks at the
// paper's configuration (Section 8: m = 1, ω = 2π, h = 1/15).

#include <simpson/energy.hpp>
#include <simpson/precision.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/three_term_scheme.hpp>

#include <CLI/CLI.hpp>
#include <boost/math/constants/constants.hpp>
#include <fmt/core.h>

#include <cstdio>
#include <exception>
#include <sstream>
#include <string>
#include <vector>

namespace {

/// 2π in Real; for exact rationals, 2π rounded to a 100-digit binary float, then exact.
template <class Real>
Real two_pi() {
  if constexpr (simpson::is_exact_v<Real>) {
    return Real(boost::math::constants::two_pi<simpson::bin100>());
  } else {
    return boost::math::constants::two_pi<Real>();
  }
}

/// A value in decimal with `digits` significant digits; rationals are shown through bin100.
template <class Real>
std::string decimal(const Real& v, int digits) {
  if constexpr (simpson::is_exact_v<Real>) {
    if (v == 0) return "0 (exact)";
    return simpson::to_string(simpson::bin100(v), digits);
  } else {
    return simpson::to_string(v, digits);
  }
}

struct row {
  std::string precision, epsilon, alpha, beta, gamma, det_minus_one, discriminant, energy_change;
};

row paper_configuration_row(const simpson::precision& prec) {
  return prec.visit([&](auto tag) {
    using Real = typename decltype(tag)::type;
    const simpson::oscillator_parameters<Real> par(Real(1), two_pi<Real>(), Real(1) / 15);
    const simpson::one_step_matrix<Real> phi3 = simpson::simpson_map(par);  // (Phi3)
    const simpson::phase_point<Real> y{par.m() * par.omega(), Real(0)};     // q = sin ωt, p = mω cos ωt at t = 0
    const Real energy_change =
        simpson::discrete_energy(par, phi3 * y) - simpson::discrete_energy(par, y);
    const int digits = 20;
    return row{prec.name(),
               prec.epsilon(),
               decimal(phi3.alpha, digits),
               decimal(phi3.beta, digits),
               decimal(phi3.gamma, digits),
               decimal(Real(simpson::determinant(phi3) - 1), 3),
               decimal(simpson::discriminant(par.omega2_h2()), 3),
               decimal(energy_change, 3)};
  });
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"simpson-verify: checks the claims of the symplectic Simpson paper"};
  app.set_version_flag("--version", std::string("simpson-verify ") + SIMPSON_VERSION);
  std::vector<std::string> precision_names;
  app.add_option("--precisions", precision_names, "comma-separated precisions (default: all)")->delimiter(',');
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);  // --help, --version
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
    return 2;
  }

  try {
    std::vector<simpson::precision> precisions;
    for (const std::string& name : precision_names) precisions.push_back(simpson::precision::parse(name));
    if (precisions.empty()) precisions = simpson::default_precisions();

    fmt::print("Phi3 at the paper's configuration: m = 1, omega = 2 pi, h = 1/15, y = (p, q) = (m omega, 0)\n");
    fmt::print("(rational: omega = 2 pi rounded to bin100, then exact; its entries are shown to 20 digits)\n\n");
    fmt::print("{:<12} {:<10} {:<27} {:<27} {:<27} {:<11} {:<11} {}\n", "precision", "epsilon", "alpha = delta",
               "beta", "gamma", "det-1", "Delta", "Hd(Phi3 y)-Hd(y)");
    for (const simpson::precision& prec : precisions) {
      const row r = paper_configuration_row(prec);
      fmt::print("{:<12} {:<10} {:<27} {:<27} {:<27} {:<11} {:<11} {}\n", r.precision, r.epsilon, r.alpha, r.beta,
                 r.gamma, r.det_minus_one, r.discriminant, r.energy_change);
    }
  } catch (const std::invalid_argument& e) {
    std::fprintf(stderr, "simpson-verify: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "simpson-verify: error: %s\n", e.what());
    return 1;
  }
  return 0;
}
