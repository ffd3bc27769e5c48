// The main job's first table: Φ_3 and its checks at the paper's configuration (Section 8:
// m = 1, ω = 2π, h = 1/15), in each precision.

#include <simpson/energy.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/three_term_scheme.hpp>
#include <simpson/verify/paper_configuration.hpp>

#include <boost/math/constants/constants.hpp>

namespace simpson::verify {
namespace {

/// 2π in Real; for exact rationals, 2π rounded to bin100, then exact.
template <class Real>
Real two_pi() {
  if constexpr (is_exact_v<Real>) {
    return Real(boost::math::constants::two_pi<bin100>());
  } else {
    return boost::math::constants::two_pi<Real>();
  }
}

/// Decimal text; rationals through bin100 (their exact fractions have hundreds of digits).
template <class Real>
std::string decimal(const Real& v, int digits) {
  if constexpr (is_exact_v<Real>) {
    if (v == 0) return "0";
    return simpson::to_string(bin100(v), digits);
  } else {
    return simpson::to_string(v, digits);
  }
}

}  // namespace

json paper_configuration(const std::vector<precision>& precisions) {
  json rows = json::array();
  for (const precision& prec : precisions) {
    rows.push_back(prec.visit([&](auto tag) {
      using Real = typename decltype(tag)::type;
      const oscillator_parameters<Real> par(Real(1), two_pi<Real>(), Real(1) / 15);
      const one_step_matrix<Real> phi3 = simpson_map(par);          // (Phi3)
      const phase_point<Real> y{par.m() * par.omega(), Real(0)};  // q = sin ωt, p = mω cos ωt at t = 0
      const Real energy_change = discrete_energy(par, phi3 * y) - discrete_energy(par, y);
      return json{{"precision", prec.name()},
                  {"epsilon", prec.epsilon()},
                  {"alpha_equals_delta", decimal(phi3.alpha, 20)},
                  {"beta", decimal(phi3.beta, 20)},
                  {"gamma", decimal(phi3.gamma, 20)},
                  {"det_minus_one", decimal(Real(determinant(phi3) - 1), 3)},
                  {"discriminant", decimal(discriminant(par.omega2_h2()), 6)},
                  {"hd_change_one_step", decimal(energy_change, 3)}};
    }));
  }
  return json{{"parameters", "m = 1, omega = 2 pi, h = 1/15, y = (p, q) = (m omega, 0); rational: omega = 2 pi rounded to bin100, then exact"},
              {"rows", rows}};
}

}  // namespace simpson::verify
