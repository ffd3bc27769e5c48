#include <simpson/verify/printed_checks.hpp>

#include <simpson/verify/paper_reading.hpp>

#include <simpson/energy.hpp>
#include <simpson/internal_node.hpp>
#include <simpson/reduced_lagrangian.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/simpson_momentum.hpp>
#include <simpson/three_term_scheme.hpp>

#include <cctype>
#include <chrono>
#include <functional>
#include <map>
#include <sstream>

namespace simpson::verify {
namespace {

using GiNaC::ex;

std::string text_of(const ex& e) { return canonical_text(e); }

/// TeX with its runs of white space folded to one space, for reports.
std::string folded(const std::string& tex) {
  std::string out;
  for (const char c : tex) {
    const bool space = std::isspace(static_cast<unsigned char>(c)) != 0;
    if (space && (out.empty() || out.back() == ' ')) continue;
    out += space ? ' ' : c;
  }
  while (!out.empty() && out.back() == ' ') out.pop_back();
  return out;
}

/// What the GiNaC kernel found for one printed formula.
struct printed_outcome {
  bool holds = false;
  bool property = false;   // a property of the printed formula (det = 1, conservation): fails, not erratum
  std::string proved;      // what was shown, in words and formulas
  std::string correction;  // the derived formula, when the printed one differs
};

/// The oscillator's parameters and states as GiNaC symbols shared with the reader.
struct symbolic_oscillator {
  explicit symbolic_oscillator(tex_symbols& s)
      : m(s["m"]), omega(s["omega"]), h(s["h"]), q_l(s["q_l"]), q_r(s["q_r"]), p(s["p"]), q(s["q"]), par{m, omega, h} {}
  ex m, omega, h, q_l, q_r, p, q;
  oscillator_parameters<ex> par;
};

/// printed − derived normalised: zero proves the identity as rational functions of every symbol.
printed_outcome compare(const std::string& what, const ex& printed, const ex& derived) {
  const ex difference = GiNaC::normal(printed - derived);
  if (difference.is_zero()) return {true, false, "printed " + what + " − derived = 0 (normal form, all symbols free)", ""};
  return {false, false, "printed " + what + " − derived = " + text_of((difference)) + " ≠ 0",
          "as derived: " + text_of((GiNaC::normal(derived)))};
}

one_step_matrix<ex> as_map(const ex& m) {
  const GiNaC::matrix& M = GiNaC::ex_to<GiNaC::matrix>(m);
  return {M(0, 0), M(0, 1), M(1, 0), M(1, 1)};
}

printed_outcome check_phi3(const paper_reading& r, symbolic_oscillator& o, bool property) {
  const ex printed = r.at("Phi3").value;
  if (!GiNaC::is_a<GiNaC::matrix>(printed) || GiNaC::ex_to<GiNaC::matrix>(printed).rows() != 2 ||
      GiNaC::ex_to<GiNaC::matrix>(printed).cols() != 2) {
    return {false, true, "the printed Φ₃ is not a 2 × 2 matrix: " + text_of(printed), ""};
  }
  const one_step_matrix<ex> phi = as_map(printed);
  if (property) {
    const ex det = GiNaC::normal(phi.alpha * phi.delta - phi.beta * phi.gamma - 1);
    if (det.is_zero()) return {true, true, "det(printed Φ₃) − 1 = 0 (normal form, symbolic m, omega, h)", ""};
    return {false, true, "det(printed Φ₃) − 1 = " + text_of((det)) + " ≠ 0", ""};
  }
  const one_step_matrix<ex> derived = simpson_map(o.par);
  const ex diff = GiNaC::normal(phi.alpha - derived.alpha) + GiNaC::normal(phi.beta - derived.beta) * o.p +
                  GiNaC::normal(phi.gamma - derived.gamma) * o.q + GiNaC::normal(phi.delta - derived.delta) * o.p * o.q;
  if (GiNaC::normal(diff).is_zero()) return {true, false, "printed Φ₃ − derived Φ₃ = 0, entry by entry (normal form)", ""};
  std::string entries;
  const char* names[] = {"alpha", "beta", "gamma", "delta"};
  const ex printed_entries[] = {phi.alpha, phi.beta, phi.gamma, phi.delta};
  const ex derived_entries[] = {derived.alpha, derived.beta, derived.gamma, derived.delta};
  std::string correction = "as derived: ";
  for (int k = 0; k < 4; ++k) {
    const ex d = GiNaC::normal(printed_entries[k] - derived_entries[k]);
    if (!d.is_zero()) entries += std::string(entries.empty() ? "" : "; ") + names[k] + ": printed − derived = " + text_of((d));
    correction += std::string(k ? ", " : "") + names[k] + " = " + text_of((GiNaC::normal(derived_entries[k])));
  }
  return {false, false, entries, correction};
}

printed_outcome check_hd_invariance(const paper_reading& r, symbolic_oscillator& o) {
  // H_d as printed, with Φ₃ as printed: H_d(Φ₃ y) − H_d(y) for symbolic p, q.
  const ex hd = r.at("hamiltonien-discret").value;
  const ex printed_phi = r.at("Phi3").value;
  if (!GiNaC::is_a<GiNaC::matrix>(printed_phi)) return {false, true, "the printed Φ₃ is not a matrix", ""};
  const one_step_matrix<ex> phi = as_map(printed_phi);
  const ex p1 = phi.alpha * o.p + phi.beta * o.q, q1 = phi.gamma * o.p + phi.delta * o.q;
  const ex change = GiNaC::normal(hd.subs(GiNaC::lst{o.p == p1, o.q == q1}) - hd);
  if (!change.is_zero()) {
    return {false, true, "printed H_d(printed Φ₃ y) − H_d(y) = " + text_of((change)) + " ≠ 0", ""};
  }
  // And it is the H_d the core defines (hamiltonien-discret), not merely some conserved form.
  const printed_outcome same = compare("H_d", hd, discrete_energy(o.par, phase_point<ex>{o.p, o.q}));
  if (!same.holds) return {false, true, same.proved, ""};
  return {true, true, "printed H_d(printed Φ₃ y) − H_d(y) = 0 and printed H_d − derived H_d = 0 (normal forms, symbolic m, omega, h, p, q)", ""};
}

/// T_h(q_j): the left side of (schema-ordre-3) on the exact solution through (p_j, q_j), q(t ± h) =
/// q_j cos ωh ± p_j/(mω) sin ωh, expanded by GiNaC in h. The printed display claims it is
/// ω⁶h⁴q_j/1440 + O(h⁶): the difference of the two must have no term below h⁶.
printed_outcome check_truncation(const paper_reading& r, symbolic_oscillator& o, tex_symbols& symbols) {
  const ex printed = r.at("truncation-error").value;
  const ex q = symbols["q_j"], p = symbols["p_j"];
  const ex c = GiNaC::cos(o.omega * o.h), s = GiNaC::sin(o.omega * o.h);
  const ex shift = p / (o.m * o.omega) * s;
  const ex residual = three_term_residual(o.par, ex(q * c - shift), q, ex(q * c + shift));
  // The printed order term O(h^k) says up to which power the two must agree.
  int order = 0;
  ex printed_terms = 0;
  const ex expanded = GiNaC::expand(printed);
  for (std::size_t k = 0; k < (GiNaC::is_a<GiNaC::add>(expanded) ? expanded.nops() : 1); ++k) {
    const ex term = GiNaC::is_a<GiNaC::add>(expanded) ? expanded.op(k) : expanded;
    if (GiNaC::is_a<GiNaC::function>(term) && GiNaC::ex_to<GiNaC::function>(term).get_name() == "Order") {
      order = term.op(0).degree(o.h);
    } else {
      printed_terms += term;
    }
  }
  if (order == 0) return {false, true, "the printed truncation error has no order term O(h^k)", ""};
  const ex difference = GiNaC::series_to_poly(GiNaC::series(residual - printed_terms, o.h == 0, order));
  const ex low = GiNaC::normal(difference);
  if (low.is_zero()) {
    return {true, false,
            "T_h(q_j) − printed terms = O(h^" + std::to_string(order) + ") (GiNaC series in h of the scheme's residual on the "
            "exact solution, symbolic m, omega, p_j, q_j)", ""};
  }
  const ex derived = GiNaC::series_to_poly(GiNaC::series(residual, o.h == 0, order));
  return {false, false, "T_h(q_j) − printed terms = " + text_of(low) + " + O(h^" + std::to_string(order) + ")",
          "as derived: T_h(q_j) = " + text_of(derived) + " + O(h^" + std::to_string(order) + ")"};
}

/// A reading is the claim's own copy: a check may add symbols (q_j, p_j) to it.
using printed_check = std::function<printed_outcome(paper_reading&, symbolic_oscillator&)>;

struct formula_claim {
  std::vector<std::string> formulas;  // the printed formulas the claim reads
  printed_check check;
};

const std::map<std::string, formula_claim>& formula_claims() {
  static const std::map<std::string, formula_claim> claims{
      {"qm-harmonic",
       {{"qm-oscillateur-harmonique"},
        [](const paper_reading& r, symbolic_oscillator& o) {
          return compare("q_m", r.at("qm-oscillateur-harmonique").value, harmonic_internal_node(o.par, o.q_l, o.q_r));
        }}},
      {"reduced-lagrangian",
       {{"Lagrangien-reduit"},
        [](const paper_reading& r, symbolic_oscillator& o) {
          return compare("L_h^r", r.at("Lagrangien-reduit").value, reduced_lagrangian(o.par, o.q_l, o.q_r));
        }}},
      {"discriminant-factorization",
       {{"discriminant-factorized"},
        [](const paper_reading& r, symbolic_oscillator& o) {
          // Δ = b² − 4ac of the characteristic equation of (schema-ordre-3), at x = ω²h².
          return compare("Δ", r.at("discriminant-factorized").value, discriminant(ex(o.omega * o.omega * o.h * o.h)));
        }}},
      {"momentum-order-3",
       {{"moment-ordre-3"},
        [](const paper_reading& r, symbolic_oscillator& o) {
          return compare("p_r", r.at("moment-ordre-3").value, simpson_momentum(o.par, o.q_l, o.q_r));
        }}},
      {"phi3-elimination", {{"Phi3"}, [](const paper_reading& r, symbolic_oscillator& o) { return check_phi3(r, o, false); }}},
      {"phi3-det", {{"Phi3"}, [](const paper_reading& r, symbolic_oscillator& o) { return check_phi3(r, o, true); }}},
      {"hd-invariance", {{"hamiltonien-discret", "Phi3"}, check_hd_invariance}},
      {"truncation-1440",
       {{"truncation-error"},
        [](paper_reading& r, symbolic_oscillator& o) { return check_truncation(r, o, r.symbols); }}},
  };
  return claims;
}

}  // namespace

bool reads_printed_formula(const std::string& claim_id) { return formula_claims().count(claim_id) > 0; }

claim_result check_claim(const claim& c, const run_context& ctx) {
  claim_result result = c.check(ctx);
  const auto it = formula_claims().find(c.id);
  if (!ctx.paper || it == formula_claims().end()) return result;
  // The reader's symbols are shared: a copy of the reading keeps the parsed formulas and their symbols.
  paper_reading reading = *ctx.paper;
  symbolic_oscillator oscillator(reading.symbols);
  const auto start = std::chrono::steady_clock::now();
  const printed_outcome outcome = it->second.check(reading, oscillator);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  json printed = json::array();
  for (const std::string& name : it->second.formulas) {
    const printed_formula& f = reading.at(name);
    printed.push_back({{"label", f.source.locator}, {"line", f.source.line}, {"tex", folded(f.source.tex)},
                       {"parsed", text_of(f.value)}});
  }
  result.printed = {{"source", reading.origin}, {"formulas", printed}};
  result.evidence["kernels"] = {
      {"own", "the claim's check above: our transcription, rational functions of theta with the grid lemma"},
      {"ginac", {{"statement", outcome.proved}, {"holds", outcome.holds}}}};
  result.printed_seconds = seconds;
  if (!outcome.holds) {
    const bool was_holding = result.outcome == verdict::holds;
    const verdict printed = outcome.property || outcome.correction.empty() ? verdict::fails : verdict::erratum;
    // The weaker of the two: an own-kernel `fails` is never softened to an erratum.
    result.outcome = result.outcome == verdict::fails ? verdict::fails : printed;
    if (result.outcome == verdict::erratum && was_holding) result.correction = outcome.correction;
    result.note = (was_holding ? "The formula as printed in the paper's source differs from the derived one: "
                               : "Also, as printed: ") + outcome.proved + (result.note.empty() ? "" : " " + result.note);
  }
  return result;
}

}  // namespace simpson::verify
