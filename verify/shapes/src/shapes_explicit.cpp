// The explicit-map shape (shape_support.hpp): whether a printed one-step map is explicit, read as the
// field defines it, against the word a sentence uses.

#include <simpson/shapes/one_variable.hpp>
#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/coq_export.hpp>
#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/sentence_holes.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// Δ_δ^k e at the step: Σ_i (−1)^(k−i) C(k, i) e(step + i δ), δ a fresh symbol. Zero exactly when e
/// is a polynomial of degree < k in the step.
ex finite_difference(const ex& e, const GiNaC::symbol& step, const GiNaC::symbol& delta, unsigned k) {
  ex sum = 0;
  for (unsigned i = 0; i <= k; ++i) {
    const ex shifted = e.subs(GiNaC::exmap{{step, step + i * delta}}, GiNaC::subs_options::no_pattern);
    sum += ((k - i) % 2 ? -1 : 1) * GiNaC::binomial(GiNaC::numeric(k), GiNaC::numeric(i)) * shifted;
  }
  return sum;
}

std::vector<GiNaC::symbol> symbols_of(const ex& e) {
  std::vector<GiNaC::symbol> out;
  std::set<std::string> seen;
  for (auto it = e.preorder_begin(); it != e.preorder_end(); ++it) {
    if (GiNaC::is_a<GiNaC::symbol>(*it) && seen.insert(GiNaC::ex_to<GiNaC::symbol>(*it).get_name()).second) out.push_back(GiNaC::ex_to<GiNaC::symbol>(*it));
  }
  return out;
}

std::vector<ex> terms_of(const ex& polynomial) {
  const ex expanded = GiNaC::expand(polynomial);
  if (!GiNaC::is_a<GiNaC::add>(expanded)) return {expanded};
  return std::vector<ex>(expanded.begin(), expanded.end());
}

/// Whether a polynomial is positive wherever the `positive` symbols are: every coefficient positive,
/// and each symbol of odd degree in a term among the positive ones (a term is then positive, or a
/// square times a positive number). A sufficient criterion; false says only that it does not apply.
bool positive_by_its_terms(const ex& polynomial, const std::set<std::string>& positive) {
  for (const ex& term : terms_of(polynomial)) {
    ex coefficient = term;
    for (const GiNaC::symbol& s : symbols_of(term)) {
      const int power = term.degree(s);
      if (power % 2 != 0 && !positive.count(s.get_name())) return false;
      coefficient = coefficient.coeff(s, power);
    }
    if (!GiNaC::is_a<GiNaC::numeric>(coefficient) || !GiNaC::ex_to<GiNaC::numeric>(coefficient).is_positive()) return false;
  }
  return true;
}

/// The square roots of each term's even part (h ω for 2 h² ω²): nra is told 0 <= each squared.
std::vector<ex> square_hints(const ex& polynomial) {
  std::vector<ex> hints;
  for (const ex& term : terms_of(polynomial)) {
    ex root = 1;
    for (const GiNaC::symbol& s : symbols_of(term)) root *= GiNaC::pow(s, term.degree(s) / 2);
    if (GiNaC::is_a<GiNaC::numeric>(root)) continue;
    if (std::none_of(hints.begin(), hints.end(), [&](const ex& h) { return (h - root).is_zero(); })) hints.push_back(root);
  }
  return hints;
}


/// The map read entry by entry: whether each is a polynomial in the step (GiNaC's normal form, and our
/// kernel's finite difference), its denominators each once, whether each is positive by its terms,
/// and the Coq goals of their signs.
struct map_entries {
  bool polynomial = true, own_polynomial = true, own_decided = true, regular = true;
  std::vector<std::string> denominators, own_evidence;
  std::vector<proof_goal> goals;
};

map_entries read_map_entries(const GiNaC::matrix& map, const GiNaC::symbol& step, const std::set<std::string>& positive,
                             const std::vector<ex>& positive_symbols) {
  map_entries out;
  bool &polynomial = out.polynomial, &own_polynomial = out.own_polynomial, &own_decided = out.own_decided, &regular = out.regular;
  std::vector<std::string> &denominators = out.denominators, &own_evidence = out.own_evidence;
  std::vector<proof_goal>& goals = out.goals;
  const GiNaC::symbol delta("delta_step");
  GiNaC::exmap inside;
  for (const ex& s : positive_symbols) inside[s] = 1;
  for (unsigned r = 0; r < map.rows(); ++r) {
    for (unsigned c = 0; c < map.cols(); ++c) {
      const ex entry = map(r, c);
      const ex normal = GiNaC::normal(entry);
      const ex den = GiNaC::denom(normal);
      const bool entry_polynomial = !den.has(step);
      polynomial = polynomial && entry_polynomial;
      const unsigned k = static_cast<unsigned>(GiNaC::numer(normal).degree(step)) + 1;
      const kernel_decision own = kernel_decides_zero(finite_difference(entry, step, delta, k));
      own_decided = own_decided && own.outcome != kernel_decision::result::not_applicable;
      own_polynomial = own_polynomial && own.outcome == kernel_decision::result::zero;
      own_evidence.push_back(fmt::format("entry ({}, {}): Δ^{} in {} {}", r + 1, c + 1, k, step.get_name(),
                                         own.outcome == kernel_decision::result::zero      ? "is zero (" + own.evidence + ")"
                                         : own.outcome == kernel_decision::result::nonzero ? "is not zero (" + own.evidence + ")"
                                                                                           : "not decided (" + own.evidence + ")"));
      if (GiNaC::is_a<GiNaC::numeric>(den)) continue;
      // Each denominator once, without its content as a polynomial in the step (the factors free of
      // it): 2 h² ω² + 48, 12 h² ω² + 288 and m h² ω² + 24 m are one.
      const ex primitive = GiNaC::factor(GiNaC::expand(den).primpart(step));
      const std::string text = text_of(primitive);
      if (std::find(denominators.begin(), denominators.end(), text) != denominators.end()) continue;
      denominators.push_back(text);
      const bool positive_denominator = positive_by_its_terms(primitive, positive);
      regular = regular && positive_denominator;
      if (positive_denominator) {
        goals.push_back(sign_goal(fmt::format("denominator_{}", denominators.size()), primitive, 1, positive_symbols, inside));
        goals.back().squares = square_hints(primitive);
      }
    }
  }
  return out;
}

/// Our kernel on each denominator with the other positive symbols at 1: its positive roots in the
/// step by Sturm sequences. None, and positive at a step: it confirms GiNaC's sign read from the
/// terms (which holds for every positive value, Coq checking each); a root refutes "for every step"
/// there.
struct own_signs {
  std::optional<std::string> pole;
  bool positive = true, applies = true;
  std::vector<std::string> lines;
  std::string at_text;  // " at ω = 1, ..." (the other positive symbols)
};

own_signs own_denominator_signs(const GiNaC::matrix& map, const GiNaC::symbol& step, const std::vector<ex>& positive_symbols) {
  const std::string h = step.get_name();
  own_signs out;
  std::optional<std::string>& pole = out.pole;
  bool &own_positive = out.positive, &own_applies = out.applies;
  std::vector<std::string>& own_lines = out.lines;
  GiNaC::exmap at_one;
  for (const ex& p : positive_symbols) {
    if (!p.is_equal(step)) at_one[p] = 1;
  }
  std::vector<ex> all_denominators;
  for (unsigned r = 0; r < map.rows(); ++r) {
    for (unsigned c = 0; c < map.cols(); ++c) {
      const ex den = GiNaC::denom(GiNaC::normal(map(r, c)));
      if (GiNaC::is_a<GiNaC::numeric>(den)) continue;
      const ex primitive = GiNaC::factor(GiNaC::expand(den).primpart(step));
      if (std::none_of(all_denominators.begin(), all_denominators.end(), [&](const ex& d) { return text_of(d) == text_of(primitive); })) {
        all_denominators.push_back(primitive);
      }
    }
  }
  for (const ex& d : all_denominators) {
    try {
      const simpson::verify::polynomial at = as_polynomial(GiNaC::expand(d.subs(at_one)), step);
      const std::vector<positive_root> roots = positive_roots(at);
      const bool positive_somewhere = at.evaluate(rational(1)) > 0;
      if (!roots.empty() && !pole) pole = fmt::format("{} = 0 at {} = {} (the other positive symbols 1)", text_of(d), h, root_text(roots.front()));
      own_positive = own_positive && roots.empty() && positive_somewhere;
      own_lines.push_back(fmt::format("{}: {} positive root{} in {} (Sturm sequences){}", text_of(d), roots.size(), roots.size() == 1 ? "" : "s", h,
                                      roots.empty() ? (positive_somewhere ? ", positive" : ", negative") : ""));
    } catch (const std::invalid_argument&) {  // a coefficient that is no rational number there
      own_applies = false;
    }
  }
  std::vector<std::string> ones;  // in the record's order
  for (const ex& p : positive_symbols) {
    if (!p.is_equal(step)) ones.push_back(text_of(p) + " = 1");
  }
  out.at_text = ones.empty() ? std::string() : fmt::format(" at {}", fmt::join(ones, ", "));
  return out;
}

}  // namespace

/// "is an explicit scheme", as the field defines it: y_{j+1} follows from y_j with no equation to
/// solve (Hairer, Nørsett and Wanner, I, II.1). On a linear problem the one-step map of such a
/// scheme is a polynomial in the step (a finite chain of force evaluations and additions); a
/// denominator that depends on the step is the inverse of a step equation that was solved. Decided
/// entry by entry: GiNaC's normal form (its denominator free of the step), and our kernel's finite
/// difference Δ^k in the step, zero exactly for a polynomial of degree < k (k one more than the
/// numerator's degree). The sentence's hole {kind} says "explicit" or "implicit". The denominators'
/// positivity (every step, the `positive` symbols positive) is what the words can mean instead: the
/// map in closed form and regular; Coq checks each denominator's sign.
decider_evidence explicit_map_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const GiNaC::matrix map = as_square_matrix(read.formula("map"), reference_of(call, "map"));
  const GiNaC::symbol step = read.symbols("step").front();
  std::set<std::string> positive{step.get_name()};
  std::vector<ex> positive_symbols{step};
  if (read.has("positive")) {
    for (const GiNaC::symbol& s : read.symbols("positive")) {
      if (positive.insert(s.get_name()).second) positive_symbols.push_back(s);
    }
  }
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  const std::string stated = said.choice("kind", hole_named("kind").phrases);
  const map_entries entries = read_map_entries(map, step, positive, positive_symbols);
  const bool polynomial = entries.polynomial, own_polynomial = entries.own_polynomial, own_decided = entries.own_decided,
             regular = entries.regular;
  const std::vector<std::string>& denominators = entries.denominators;
  const std::vector<std::string>& own_evidence = entries.own_evidence;
  std::vector<proof_goal> goals = entries.goals;
  claim_result result;
  result.printed = read.printed();
  const std::string map_ref = reference_of(call, "map");
  const std::string h = step.get_name();
  result.evidence["exact"] = {
      {"statement", fmt::format("({}) gives the next state in closed form for every {} > 0 (explicit on this linear problem: the verdict's "
                                "statement); and, apart, whether every entry is a polynomial in {} (explicit as a method: no step equation "
                                "solved; when not, a wording remark)",
                                map_ref, h, h)},
      {"ginac", polynomial ? "a polynomial: no denominator depends on " + h
                           : fmt::format("not a polynomial: the denominators {} depend on {}", fmt::join(denominators, ", "), h)},
      {"own", own_decided ? fmt::format("{}: {}", own_polynomial ? "a polynomial" : "not a polynomial", fmt::join(own_evidence, "; "))
                          : fmt::format("not applicable: {}", fmt::join(own_evidence, "; "))},
      {"denominators", denominators},
      {"regular", regular ? fmt::format("every denominator is positive for {} > 0 (its terms)", fmt::join(positive, ", "))
                          : "not shown: a denominator's terms are not all positive"}};
  result.evidence["stated"] = stated;
  // The words as the field reads them (the policy: an erratum is false under every reasonable
  // reading). "Explicit", said of a scheme on a linear problem whose map the text gives, holds when
  // that map gives the next state in closed form for every step: its denominators do not vanish. A
  // denominator in the step is what solving the step's equation leaves, so as a method the scheme is
  // implicit: a wording remark, not an erratum. "Implicit" holds when a denominator depends on the
  // step, and is false of a map that is a polynomial in it.
  decider_evidence e;
  e.statement = "whether the map is a polynomial in the step";
  const std::string denominators_text = fmt::format("{} {}", denominators.size() == 1 ? "denominator" : "denominators", fmt::join(denominators, ", "));
  if (stated == "explicit") {
    e.statement = "whether the map's denominators are positive for every step";
    const own_signs own = own_denominator_signs(map, step, positive_symbols);
    const std::optional<std::string>& pole = own.pole;
    const bool own_positive = own.positive, own_applies = own.applies;
    const std::vector<std::string>& own_lines = own.lines;
    const std::string& at_text = own.at_text;
    result.evidence["exact"]["ginac"] = regular ? fmt::format("holds: every denominator is positive for {} > 0 (its terms); {}", fmt::join(positive, ", "),
                                                              result.evidence["exact"]["ginac"].get<std::string>())
                                                : fmt::format("not shown: a denominator's terms are not all positive; {}", result.evidence["exact"]["ginac"].get<std::string>());
    result.evidence["exact"]["own"] = !own_applies ? "not applicable: a denominator's coefficients are not rational numbers" + at_text
                                      : own_lines.empty() ? std::string("holds: no denominator depends on ") + h
                                                          : fmt::format("{}{}: {}", own_positive ? "holds" : "fails", at_text, fmt::join(own_lines, "; "));
    e.ginac = regular ? answer::holds : pole ? answer::fails : answer::none;
    e.own = !own_applies ? answer::none : own_positive ? (regular ? answer::holds : answer::none) : pole ? answer::fails : answer::none;
    if (!regular) {
      if (!pole) {
        result.note = fmt::format("A denominator of ({}) is not shown positive for every {} > 0, nor shown to vanish: whether the map is defined for every "
                                  "step is not decided.",
                                  map_ref, h);
        return beyond_reach(std::move(result));
      }
      result.correction = fmt::format("({}) is not in closed form for every {} > 0: {}, and the step is not defined there", map_ref, h, *pole);
      result.amendments.push_back(amendment_in_words("the scheme's kind", said.words("kind"), "explicit only where " + *pole + " does not hold"));
    } else if (!polynomial) {
      result.remark_kind = finding::wording;
      result.remark = fmt::format("Explicit only in the sense that on this linear problem ({}) gives the next state in closed form, regular for every "
                                  "{} > 0, as every linear one-step method does, an implicit one too. In the usual sense the scheme is implicit: the "
                                  "entries are rational in {}, with the {} (up to factors free of {}) that solving the step's linear equation leaves; "
                                  "for a general potential that equation is nonlinear and solved at every step.",
                                  map_ref, h, h, denominators_text, h);
      result.amendments.push_back(amendment_in_words("the scheme's kind", said.words("kind"),
                                                     "explicit for this linear problem (in closed form); implicit as a method"));
    } else {
      result.note = fmt::format("The scheme is explicit: every entry of ({}) is a polynomial in {}.", map_ref, h);
    }
  } else {
    e.ginac = answer_of(!polynomial);
    e.own = own_decided ? answer_of(!own_polynomial) : answer::none;
    if (polynomial) {
      result.correction = fmt::format("The scheme is explicit: every entry of ({}) is a polynomial in {}, so no step equation is solved.", map_ref, h);
      result.amendments.push_back(amendment_in_words("the scheme's kind", said.words("kind"), "explicit: every entry of the map is a polynomial in " + h));
    } else {
      result.note = fmt::format("The scheme is implicit as a method: the entries of ({}) have the {}, which depend{} on {}.", map_ref, denominators_text,
                                denominators.size() == 1 ? "s" : "", h);
    }
  }
  if (goals.empty()) {
    result.certificate_missing = polynomial ? "no denominator depends on the step: nothing to certify" : "no denominator shown positive";
  } else {
    e.goals = std::move(goals);
  }
  e.found = std::move(result);
  return e;
}

}  // namespace simpson::verify::detail

namespace simpson::verify::detail {

/// "is explicit (implicit) for a general potential": what the scheme is with the document's
/// functions left uninterpreted. A step computes the last state of the sequence; it does so in
/// closed form when the scheme is linear in it, with a coefficient that does not vanish
/// identically, and the state is never inside the argument of a function, uninterpreted or known (q_{j+1}
/// in V'((q_j + q_{j+1})/2) makes the step a nonlinear equation for a general V, whatever the
/// harmonic case allows). GiNaC reads the structure and solves; our kernel decides that the
/// solution satisfies the scheme (that identity is the Coq certificate). The sentence's hole {kind}
/// says "explicit" or "implicit".
decider_evidence explicit_scheme_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex scheme = read.formula("scheme");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence");
  const GiNaC::symbol& next = sequence.back();
  const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
  const std::string stated = said.choice("kind", hole_named("kind").phrases);
  claim_result result;
  result.printed = read.printed();
  result.evidence["stated"] = stated;
  const std::string scheme_ref = reference_of(call, "scheme"), state = next.get_name();
  // Where the next state is an argument of a function: an uninterpreted one (V'((q_j + q_{j+1})/2))
  // or a known one (\sin q_{j+1}): a step linear in q_{j+1} outside them still solves a nonlinear
  // equation (solving for the q_{j+1} outside would leave it inside).
  std::vector<std::string> arguments_of;
  bool only_known = true;
  for (auto it = scheme.preorder_begin(); it != scheme.preorder_end(); ++it) {
    if (!GiNaC::is_a<GiNaC::function>(*it) || !it->has(next)) continue;
    only_known = only_known && !is_reader_function(*it);
    const std::string text = text_of(*it);
    if (std::find(arguments_of.begin(), arguments_of.end(), text) == arguments_of.end()) arguments_of.push_back(text);
  }
  std::string computed, why;
  std::optional<ex> solution;
  if (!arguments_of.empty()) {
    computed = "implicit";
    why = fmt::format("{} is in the argument of {}: {}the step solves a nonlinear equation in it", state, fmt::join(arguments_of, ", "),
                      only_known ? "" : "for a general function ");
  } else {
    const ex normal = GiNaC::normal(scheme);
    const ex numerator = GiNaC::numer(normal);
    if (GiNaC::denom(normal).has(next)) {
      computed = "implicit";
      why = fmt::format("{} is in a denominator of the scheme: the step solves a nonlinear equation in it", state);
    } else if (numerator.degree(next) == 0) {
      result.note = fmt::format("({}) does not involve {}: it computes no step.", scheme_ref, state);
      result.certificate_missing = "no step to certify";
      return beyond_reach(std::move(result));
    } else if (numerator.degree(next) > 1) {
      computed = "implicit";
      why = fmt::format("the scheme is of degree {} in {}: the step solves a polynomial equation", numerator.degree(next), state);
    } else {
      computed = "explicit";
      solution = GiNaC::normal(-numerator.coeff(next, 0) / numerator.coeff(next, 1));
      why = fmt::format("the scheme is linear in {}, never inside a function's argument: {} = {}", state, state, text_of(*solution));
    }
  }
  json exact = {{"statement", fmt::format("({}) gives {} in closed form, its functions left general", scheme_ref, state)},
                {"ginac", (computed == "explicit" ? "holds: " : "fails: ") + why}};
  // GiNaC reads the structure and solves; our kernel checks the solution, so it confirms GiNaC's
  // answer on the words (or refutes the solution it rests on).
  decider_evidence e;
  e.statement = "the step's solution";
  e.ginac = answer_of(stated == computed);
  if (solution) {
    const kernel_decision own = kernel_decides_zero(scheme.subs(GiNaC::exmap{{next, *solution}}, GiNaC::subs_options::no_pattern));
    exact["own"] = own.outcome == kernel_decision::result::zero      ? fmt::format("holds: ({}) at {} = the solution is 0 ({})", scheme_ref, state, own.evidence)
                   : own.outcome == kernel_decision::result::nonzero ? "contradicts GiNaC: " + own.evidence
                                                                     : "not applicable: " + own.evidence;
    e.own = confirming(e.ginac, own);
    e.goals = std::vector<proof_goal>{decided("solution", scheme.subs(GiNaC::exmap{{next, *solution}}, GiNaC::subs_options::no_pattern), 0)};
  } else {
    exact["own"] = "not applicable: where the next state stands (a function's argument, a denominator, a power) is read from the formula's structure";
    result.certificate_missing = "a structural fact (where the next state stands), no identity to certify";
  }
  result.evidence["exact"] = exact;
  const std::string fact = fmt::format("The scheme is {}: {}", computed, why);
  if (stated == computed) {
    result.note = fact + ".";
  } else {
    result.correction = fact + ".";
  }
  e.found = std::move(result);
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> explicit_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"explicit-map", "the sentence's {kind} (explicit or implicit) is what the printed map of a linear problem is: explicit when it gives the next state "
                       "in closed form for every step (its denominators positive), with a wording remark when a denominator depends on the step "
                       "(implicit as a method); implicit when one does",
       "map",
       with_where({{"map", argument_kind::matrix, true, "the printed one-step map"},
                   {"step", argument_kind::symbols, true, "the step h", 1},
                   {"positive", argument_kind::symbols, false, "symbols positive besides the step (m, omega), for the denominators' signs"},
                   pattern_with_hole("sentence", "the sentence's pattern: the hole {kind}, 'explicit' or 'implicit'", "kind")}),
       explicit_map_shape});
  add({"explicit-scheme", "the sentence's {kind} (explicit or implicit) is what the scheme is for the document's functions left general: explicit when it "
                          "gives its next state in closed form (linear in it, and never inside an application of a function such as V')",
       "scheme",
       with_where({{"scheme", argument_kind::formula, true, "the scheme's expression (= 0) in consecutive states, its functions (V) uninterpreted"},
                   {"sequence", argument_kind::symbols, true, "its states, the last the one a step computes (q_{j+1})"},
                   pattern_with_hole("sentence", "the sentence's pattern: the hole {kind}, 'explicit' or 'implicit'", "kind")}),
       explicit_scheme_shape});
  return all;
}

}  // namespace simpson::verify::detail
