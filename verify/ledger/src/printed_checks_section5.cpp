// Section 5's series: the derived scheme on the exact solution's Taylor polynomials, its truncation
// series (derivation-phi3), and a printed series split into its terms and its O(h^k) (the series
// shapes).

#include "derivation_support.hpp"


namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

const GiNaC::symbol& as_symbol(const ex& e) { return GiNaC::ex_to<GiNaC::symbol>(e); }

/// `scheme` (in q_{j-1}, q_j, q_{j+1}) on the exact solution through (p_j, q_j), q(t_j ± h) =
/// q_j cos ωh ± p_j/(mω) sin ωh, as a series in h to O(h^order).
/// The scheme on the exact solution through (p_j, q_j), cos ωh and sin ωh replaced by their Taylor
/// polynomials through h^(order + 2): a Laurent polynomial in h.
ex on_taylor_solution(const symbolic_derivation& d, const ex& scheme, int order) {
  // cos ωh and sin ωh as their Taylor polynomials through h^(order + 2): the scheme divides by h²
  // at most, so the series below is exact through h^(order - 1); GiNaC then expands a rational
  // function instead of sin and cos (several times faster).
  ex c = 0, s = 0, term = 1;
  for (int k = 0; k <= order + 2; ++k) {
    if (k > 0) term = term * d.omega * d.h / k;
    if (k % 2 == 0) c += (k % 4 == 0 ? 1 : -1) * term;
    else s += (k % 4 == 1 ? 1 : -1) * term;
  }
  const ex shift = d.p_j / (d.m * d.omega) * s;
  return scheme.subs(GiNaC::lst{d.q_prev == d.q_j * c - shift, d.q_next == d.q_j * c + shift});
}

ex exact_solution_series(const symbolic_derivation& d, const ex& scheme, int order) {
  return GiNaC::expand(GiNaC::series_to_poly(GiNaC::series(on_taylor_solution(d, scheme, order), d.h == 0, order)));
}

}  // namespace

GiNaC::ex normalised_scheme(const symbolic_derivation& d, const GiNaC::ex& normalised_like) {
  const ex derived = d.scheme(d.q_prev, d.q_j, d.q_next);
  const GiNaC::symbol& next = as_symbol(d.q_next);
  const ex scale = GiNaC::normal(GiNaC::expand(normalised_like).coeff(next, 1) / GiNaC::expand(GiNaC::numer(derived)).coeff(next, 1) *
                                 GiNaC::denom(derived));
  return GiNaC::normal(derived * scale);
}

GiNaC::ex truncation_series(const symbolic_derivation& d, const GiNaC::ex& normalised_like, int order) {
  return exact_solution_series(d, normalised_scheme(d, normalised_like), order);
}

}  // namespace simpson::verify::detail
