// The characteristic-polynomial shape (shape_support.hpp): a printed polynomial in r is the
// characteristic polynomial of a linear three-term scheme, the scheme taken at the geometric
// sequence q_{j-1} = 1, q_j = r, q_{j+1} = r², up to a factor free of r.

#include "shape_support.hpp"

#include "printed_check_support.hpp"

#include <fmt/format.h>

#include <array>
#include <map>
#include <optional>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// p's coefficients of r⁰, r¹, r² when p is a polynomial of degree at most 2 in r with
/// coefficients free of r; none otherwise.
std::optional<std::array<ex, 3>> quadratic_coefficients(const ex& p, const GiNaC::symbol& r) {
  const ex expanded = GiNaC::expand(p);
  if (!expanded.is_polynomial(r) || expanded.degree(r) > 2) return std::nullopt;
  std::array<ex, 3> c;
  for (int k = 0; k <= 2; ++k) c[static_cast<std::size_t>(k)] = GiNaC::normal(expanded.coeff(r, k));
  for (const ex& coefficient : c) {
    if (coefficient.has(r)) return std::nullopt;
  }
  if (!GiNaC::normal(p - (c[0] + c[1] * r + c[2] * r * r)).is_zero()) return std::nullopt;
  return c;
}

std::string power_text(const GiNaC::symbol& r, std::size_t k) {
  return k == 0 ? std::string("1") : k == 1 ? r.get_name() : r.get_name() + "^" + std::to_string(k);
}

}  // namespace

/// "This equation can be written a r² + b r + c = 0 with a = ..., b = ...": the printed polynomial
/// (its coefficients by `where`) is the scheme's at (1, r, r²) times a factor free of r. A
/// coefficient the text names without printing it (`unprinted`, c) is solved for: it is what makes
/// the two proportional, and the evidence gives it. The scale is the printed coefficient of the
/// highest power: Q_k P(r) = P_k Q(r), decided in both kernels as written, is the statement.
claim_result characteristic_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const ex scheme = read.formula("scheme");
  const std::vector<GiNaC::symbol> q = read.symbols("sequence");
  const GiNaC::symbol r = read.symbols("root").front();
  const std::vector<GiNaC::symbol> unprinted = read.has("unprinted") ? read.symbols("unprinted") : std::vector<GiNaC::symbol>{};
  const std::string scheme_ref = reference_of(call, "scheme"), printed_ref = reference_of(call, "printed");
  claim_result result;
  result.printed = read.printed();
  const auto cannot = [&](const std::string& why) {
    result.outcome = verdict::fails;
    result.note = why;
    return result;
  };
  const std::optional<three_term_coefficients> terms = linear_three_term(scheme, q);
  if (!terms) return cannot("The shape decides linear three-term schemes; (" + scheme_ref + ") is not linear in " + q[0].get_name() + ", " +
                            q[1].get_name() + ", " + q[2].get_name() + ".");
  const GiNaC::lst geometric{q[0] == 1, q[1] == r, q[2] == r * r};
  const std::array<ex, 3> derived{GiNaC::normal(terms->previous), GiNaC::normal(terms->current), GiNaC::normal(terms->next)};
  const std::optional<std::array<ex, 3>> stated = quadratic_coefficients(printed, r);
  if (!stated) return cannot("(" + printed_ref + ") is not a polynomial of degree at most 2 in " + r.get_name() + ".");
  // Each unprinted coefficient is one whole coefficient of the printed polynomial, and in no other.
  std::map<std::size_t, GiNaC::symbol> holes;
  for (const GiNaC::symbol& u : unprinted) {
    std::optional<std::size_t> at;
    for (std::size_t k = 0; k < 3; ++k) {
      if (GiNaC::normal((*stated)[k] - u).is_zero()) {
        at = k;
      } else if ((*stated)[k].has(u)) {
        at.reset();
        break;
      }
    }
    if (!at || holes.count(*at)) {
      return cannot("The unprinted " + u.get_name() + " is not one whole coefficient of (" + printed_ref + ") = " + text_of(printed) + ".");
    }
    holes.emplace(*at, u);
  }
  std::optional<std::size_t> lead;  // the printed coefficient that sets the scale
  for (std::size_t k = 3; k-- > 0;) {
    if (!holes.count(k) && !(*stated)[k].is_zero() && !derived[k].is_zero()) {
      lead = k;
      break;
    }
  }
  if (!lead) return cannot("(" + printed_ref + ") and (" + scheme_ref + ") share no nonzero printed coefficient to compare by.");
  const ex scale = GiNaC::normal((*stated)[*lead] / derived[*lead]);  // printed over derived
  GiNaC::exmap solved;
  json solved_text = json::object();
  for (const auto& [k, u] : holes) {
    solved[u] = GiNaC::normal(derived[k] * scale);
    solved_text[u.get_name()] = fmt::format("{} (the {} coefficient of ({}) at (1, {}, {}^2), times {})", text_of(solved[u]),
                                            k == 0 ? r.get_name() + "^0" : power_text(r, k), scheme_ref, r.get_name(), r.get_name(), text_of(scale));
  }
  // The statement: Q_lead · scheme(1, r, r²) = P_lead · printed, the unprinted coefficients put in.
  const ex lhs = (*stated)[*lead] * scheme.subs(geometric);
  const ex rhs = derived[*lead] * printed.subs(solved);
  const std::string what = fmt::format("({}) at {} = 1, {} = {}, {} = {}^2 is ({}) times {}", scheme_ref, q[0].get_name(), q[1].get_name(), r.get_name(),
                                       q[2].get_name(), r.get_name(), printed_ref, text_of(GiNaC::normal(1 / scale)));
  std::string correction = "as derived from (" + scheme_ref + "), scaled to the printed " + power_text(r, *lead) + " coefficient:";
  for (std::size_t k = 3; k-- > 0;) {
    correction += fmt::format(" ({}){}{}", text_of(GiNaC::normal(derived[k] * scale)), k > 0 ? " " + power_text(r, k) : std::string(), k > 0 ? " +" : "");
  }
  result = identity_verdict(call, read, "characteristic", what, lhs, rhs, correction);
  result.evidence["exact"]["characteristic_coefficients"] = {
      {"derived", {text_of(derived[0]), text_of(derived[1]), text_of(derived[2])}},
      {"printed", {text_of((*stated)[0]), text_of((*stated)[1]), text_of((*stated)[2])}}};
  if (!holes.empty()) {
    result.evidence["exact"]["unprinted"] = solved_text;
    std::string named;
    for (const auto& [k, u] : holes) {
      named += (named.empty() ? "" : ", ") + u.get_name() + " = " + text_of(solved[u]);
      for (std::size_t other = 3; other-- > 0;) {  // equal to a printed one (c = a: the roots' product is 1)
        if (!holes.count(other) && GiNaC::normal(solved[u] - (*stated)[other]).is_zero()) {
          named += ", the printed " + (other == 0 ? r.get_name() + "^0" : power_text(r, other)) + " coefficient";
          break;
        }
      }
    }
    const std::string said = "Not printed, solved from the scheme: " + named + ".";
    result.note = result.note.empty() ? said : result.note + " " + said;
  }
  return result;
}

}  // namespace simpson::verify::detail
