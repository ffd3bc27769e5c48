// Prose the paper states without a formula: the abstract's unqualified "explicit" (its "stable" is a record of
// the unconditional-stability shape), and the conventions Section 8 states (and those it leaves unstated).

#include <simpson/verify/table1_reader.hpp>
#include "claim_support.hpp"
#include "bespoke_checks.hpp"
#include <simpson/verify/readable_math.hpp>

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/table1_conventions.hpp>

#include <simpson/internal_node.hpp>

#include <fmt/format.h>

#include <cctype>
#include <map>

namespace simpson::verify::detail {
namespace {

/// The abstract's sentence: "It is a stable, explicit, and symplectic scheme satisfying the
/// conservation of an approximate energy."
quoted_sentence abstract_sentence(const run_context& ctx) {
  return quote(ctx, "It is a {qualities} scheme satisfying the conservation of an approximate energy.");
}

/// Whether the internal equation (equation-milieu-intervalle) is linear in q_m for V = q^k: its
/// second difference in q_m vanishes identically (degree <= k - 1 in q_m, so exact differences
/// decide). Linear: q_m is a closed-form function of q_l, q_r, and the step is explicit.
bool internal_equation_linear(int k, json& evidence) {
  const monomial_potential V{k};
  const symbolic h = symbolic::variable();
  const auto residual = [&](const rational& ql, const rational& qm, const rational& qr) {
    return internal_equation_residual(symbolic(1), h, [&](const symbolic& x) { return V.derivative(x); }, symbolic(ql), symbolic(qm),
                                      symbolic(qr));
  };
  bool linear = true;
  for (int qm = 0; qm <= k + 1 && linear; ++qm) {
    const symbolic second = residual(1, qm + 1, 2) - 2 * residual(1, qm, 2) + residual(1, qm - 1, 2);
    linear = second.is_zero();
  }
  evidence.push_back({{"potential", "V(q) = q^" + std::to_string(k)}, {"internal_equation_linear_in_q_m", linear}});
  return linear;
}

decider_evidence check_abstract_explicit(const run_context& ctx) {
  const quoted_sentence said = abstract_sentence(ctx);
  const std::string stated = said.containing("qualities", {{"implicit", "implicit"}, {"explicit", "explicit"}});
  // Qualified when the words restrict "explicit" to linear problems or the harmonic oscillator
  // ("linear" as a word: "nonlinear" is the opposite).
  const std::string words = said.words("qualities");
  const auto says_linear = [](const std::string& text) {
    bool found = false;
    for (std::size_t at = text.find("linear"); at != std::string::npos; at = text.find("linear", at + 1)) {
      found = found || at == 0 || std::isalpha(static_cast<unsigned char>(text[at - 1])) == 0;
    }
    return found;
  };
  const bool linear_word = says_linear(words);
  // "It" is the scheme of the sentence before: "The resulting scheme is explicited for {scope}." When
  // that scope is the harmonic oscillator (or linear problems), "explicit" is said of it, read in context;
  // words that extend it to nonlinear problems stay unqualified.
  const quoted_sentence before = quote(ctx, "The resulting scheme is explicited for {scope}. It is a");
  const std::string scope = before.words("scope");
  const bool scope_linear = scope.find("harmonic oscillator") != std::string::npos || says_linear(scope);
  before.record("scope", scope_linear ? "the harmonic oscillator or linear problems: limits \"explicit\"" : "no limit to linear problems");
  const bool nonlinear_word = words.find("nonlinear") != std::string::npos || words.find("non-linear") != std::string::npos;
  const bool qualified = !nonlinear_word && (linear_word || words.find("harmonic") != std::string::npos || scope_linear);
  json cases = json::array();
  const bool linear_case = internal_equation_linear(2, cases);
  bool every_case_linear = true;
  for (const int k : {3, 4}) every_case_linear = internal_equation_linear(k, cases) && every_case_linear;
  // (For V = q^3, q^4 the equation is not linear: the scheme is implicit as a method for a general V.)
  json evidence;
  evidence["exact"] = {{"method", "exact"},
                       {"reduction", "m = 1, h symbolic; the second difference in q_m of (equation-milieu-intervalle) at q_l = 1, "
                                     "q_r = 2, q_m = 0.." },
                       {"cases", cases},
                       {"linear_for_every_potential_tried", every_case_linear}};
  evidence["stated"] = {{"words", said.words("qualities")}, {"explicit", stated}, {"qualified", qualified},
                        {"context", "the sentence before: the resulting scheme is explicited for " + scope}};
  const std::string computed = "explicit for the harmonic oscillator (any quadratic V: the internal equation is linear in q_m, "
                               "solved in closed form, and Phi_3 follows); for a nonlinear V (V = q^3, q^4 here) each step solves "
                               "(equation-milieu-intervalle), nonlinear in q_m: an implicit step";
  if (!linear_case) return confirmed_if(false, evidence);
  const std::string fixed = "the computation (the internal equation linear in q_m for quadratic V, not for V = q^3, q^4) is the same whatever the words";
  if (stated != "explicit") return lexical(confirmed_if(true, evidence, "Computed: " + computed + "."), stated, fixed);
  // Read in context the word is Section 6's "explicit scheme" (phi3-explicit): the step in closed
  // form for the harmonic oscillator, as the sentence before limits it. True of that scheme as an
  // expert reads it (the policy: an erratum is false under every reasonable reading): it holds, with
  // the wording remark that as a method the scheme is implicit.
  if (qualified) {
    decider_evidence holds = confirmed_if(true, evidence);
    holds.found.remark_kind = finding::wording;
    holds.found.remark = "Explicit for the harmonic oscillator, to which the sentence before limits it (\"explicited for " + scope +
                         "\"): its step equation is linear in q_m, solved in closed form, and Phi_3 follows (phi3-explicit). As a method the "
                         "scheme is implicit: for a nonlinear V (V = q^3, q^4 here) the internal node's equation is nonlinear, and each step "
                         "solves it.";
    holds.found.amendments.push_back(amendment{"the scheme's kind", stated, "explicit for the harmonic oscillator; implicit as a method", false});
    return lexical(std::move(holds), stated, fixed);
  }
  return lexical(amended(words_erratum(evidence, "The scheme is " + computed,
                       "The abstract proposes the method for dynamical systems issued from the least action principle and calls it explicit "
           "without qualification, in no context that limits it to the harmonic oscillator; Section 9 says the internal node cannot be "
           "eliminated in the nonlinear case."),
                         "the scheme's kind", stated, "implicit as a method; its step in closed form for the harmonic oscillator"),
                 stated, fixed);
}

/// Section 8's stated conventions: "We have chosen q(t) = sin ωt and p(t) = m ω cos ωt, with a
/// period T = 1." Read, not typed (read_stated_solution): q and p as TeX, checked in GiNaC that q
/// solves the oscillator (q'' = -ω² q) and p = m dq/dt of it, and q's amplitude and phase taken from
/// q(0) and q'(0)/ω, ω = 2π/T. Whether they are the experiment's is the convention search's, from
/// them. Listed: what the section leaves unstated.
decider_evidence check_experiment_conventions(const run_context& ctx) {
  const stated_solution stated = read_stated_solution(paper_of(ctx).source, ctx.quotes);
  const std::string q = stated.q_text, expected_p = stated.m_dq_dt;
  const int period = static_cast<int>(stated.period);
  const bool consistent = stated.solves && stated.momentum;
  json evidence;
  evidence["exact"] = {{"method", "exact (GiNaC: q'' + omega^2 q and p - m dq/dt of the printed q and p)"},
                       {"q", q},
                       {"p_printed", stated.p_text},
                       {"m_dq_dt", expected_p},
                       {"solves", stated.solves},
                       {"period", period},
                       {"amplitude", stated.amplitude},
                       {"phase", stated.phase},
                       {"omega", period == 1 ? "2 pi" : "2 pi/" + std::to_string(period)}};
  evidence["unstated"] = json::array({"the mass m (the harness takes m = 1)",
                                      "the energy errors' definitions (the harness takes max_j |H(y_j) - H(y_0)|)",
                                      "the points the maximum runs over (the harness takes t_j, j = 0..N)",
                                      "how the momentum is rescaled in Figure 1 (the harness plots p/(m omega))"});
  evidence["harness"] = fmt::format("table1 searched from the stated solution: m = 1, T = {}, q(t) = {:.6g} sin(omega t + {:.6g})", period,
                                    stated.amplitude, stated.phase);
  if (!stated.solves) {
    return confirmed_if(false, evidence, "The printed q(t) = " + q + " does not solve q'' = -omega^2 q: it is no solution of the oscillator.");
  }
  if (!consistent) {
    return confirmed_if(false, evidence, "The printed p(t) = " + stated.p_text + " is not m dq/dt = " + expected_p +
                                             " of the printed q(t): the pair is not one solution of the oscillator.");
  }
  // Whether these are the conventions of the experiment the section reports: do they reproduce Table 1
  // as printed? The convention search (shared with table-values, run once per table) decides.
  const printed_table1 printed = read_table1(paper_of(ctx).source);
  const convention_search_result search =
      search_table1(table1_printed(printed.values, printed.orders, &printed.digits), search_start(stated), ctx.memo);
  evidence["table1"] = {{"stated_reproduce", std::to_string(search.stated.reproduced) + " of " + std::to_string(search.stated.entries.size()) +
                                                 " entries of Table 1 within their printed digits"},
                        {"reproducing_convention", search.reproducing() != nullptr ? describe(*search.reproducing()) : "none found"}};
  const std::string unstated = "Section 8 leaves unstated the mass m, the energy errors' definitions, the points the maximum runs "
                               "over, and how the momentum data of Figure 1 are rescaled (evidence 'unstated': what the harness takes).";
  if (search.stated_reproduces()) {
    return confirmed_if(true, evidence, fmt::format("The stated pair is one exact solution (p = m dq/dt) with T = {} one period, and it "
                                                    "reproduces Table 1. ", period) + unstated);
  }
  const std::vector<printed_entry> entries = table1_printed(printed.values, printed.orders, &printed.digits);
  const convention_candidate* simplest = search.simplest();
  const std::string stated_count =
      fmt::format("q(t) = {} with m = 1 reproduces {}", readable_math(stated.q_text), tally_text(tally_entries(search.stated, entries)));
  if (simplest != nullptr && (simplest->reproduced == entries.size() || search.reproducing() != nullptr)) {
    evidence["table1"]["simplest"] = table1_explanation(search, entries);
    // The stated start and Table 1 are inconsistent; a start consistent with the table is a best
    // explanation, not a proved correction: what was run cannot be recovered from the paper.
    const entry_tally stated_tally = tally_entries(search.stated, entries), best_tally = tally_entries(*simplest, entries);
    // m is unstated. From the stated q(t) the position rows do not depend on it (lemma-dimensional-
    // scaling: p and the energies scale with m, q does not): what they reproduce at m = 1 they
    // reproduce for every m.
    std::size_t position_entries = 0, position_reproduced = 0;
    for (std::size_t k = 0; k < entries.size() && k < search.stated.entries.size(); ++k) {
      if (published_rows()[k / published_meshes.size()].field != &table_errors::q || entries[k].round_off) continue;
      ++position_entries;
      position_reproduced += search.stated.entries[k].reproduced ? 1 : 0;
    }
    const std::string any_mass =
        position_reproduced == 0
            ? fmt::format("; and no other m reproduces the table: the {} entries of the state rows (errors in q) do not depend on m from the "
                          "stated q(t) (lemma-dimensional-scaling: p and the energies scale with m, q does not), and it reproduces none of them",
                          position_entries)
            : "";
    evidence["table1"]["state_rows_reproduced_for_any_m"] = fmt::format("{} of {}", position_reproduced, position_entries);
    return amended(words_erratum(evidence,
                         fmt::format("The stated solution is inconsistent with Table 1: {}{}. Table 1 is consistent with another start: {}{}. Which of the "
                                     "two, the sentence or the table's run, is wrong, the paper does not say; either correction makes them one: "
                                     "the sentence stating that start, or Table 1 recomputed from the stated solution",
                                     stated_count, any_mass, table1_explanation(search, entries),
                                     simplest->reproduced == entries.size() ? "" : "; a fit of m, the amplitude and the phase reproduces every entry (table-values)"),
                         fmt::format("The stated pair is one exact solution with T = {} one period, but not one Table 1 was computed with "
                                     "(table-values, convention search). ", period) + unstated),
                   fmt::format("Table 1 not from its stated start ({} of its {} informative entries); a start never stated reproduces {} of them",
                               stated_tally.informative_reproduced, stated_tally.informative, best_tally.informative_reproduced),
                   fmt::format("$q(t) = {}$, $p(t) = {}$", stated.q_tex, stated.p_tex),
                   fmt::format("a start consistent with Table 1 (the stated one reproduces {} of its {} informative entries at m = 1{}): either "
                               "the oscillator {}, which reproduces {} of them to their printed digits; or Table 1 recomputed from the stated one",
                               stated_tally.informative_reproduced, stated_tally.informative,
                               position_reproduced == 0 ? fmt::format(", and for no m its {} state entries, which m does not change", position_entries) : "",
                               table1_start(*simplest), best_tally.informative_reproduced));
  }
  return confirmed_if(false, evidence, "The stated pair does not reproduce Table 1, and no convention of the searched family does "
                                       "(table-values). " + unstated);
}

}  // namespace

std::optional<stated_solution> stated_table1_words(const run_context& ctx) {
  try {
    return read_stated_solution(paper_of(ctx).source);
  } catch (const text_changed&) {
    return std::nullopt;
  }
}

table1_stated search_start(const std::optional<stated_solution>& s) {
  return s ? table1_stated{s->amplitude, s->phase, s->period} : table1_stated{};
}

table1_stated stated_table1_solution(const run_context& ctx) { return search_start(stated_table1_words(ctx)); }

void add_abstract_checks(check_registry& checks) {
  checks.add("abstract-explicit", check_abstract_explicit);
}

void add_convention_checks(check_registry& checks) {
  checks.add("experiment-conventions", check_experiment_conventions);
}

}  // namespace simpson::verify::detail
