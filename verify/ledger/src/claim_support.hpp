#pragma once
// Helpers shared by the claim definitions: exact identity proofs with their evidence, and that
// evidence as a decider's (decide.hpp makes the verdict).

#include <simpson/prove/decide.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/exact_proof.hpp>
#include <simpson/verify/numeric_recheck.hpp>
#include <simpson/verify/run_memo.hpp>

#include "grid_lemma.hpp"

#include <simpson/one_step_map.hpp>

#include <map>
#include <tuple>
#include <string>
#include <typeinfo>
#include <utility>
#include <vector>

namespace simpson::verify::detail {

/// The reduction of the exact proofs in θ (exact_proof.hpp's unit_oscillator_in_theta).
inline constexpr const char* unit_reduction = "m = omega = 1, h = theta (lemma-dimensional-scaling)";

/// The outcome of an exact proof attempt and its evidence.
struct proof {
  bool proved = false;
  json evidence = json::object();
};

/// `difference` is a symbolic expression that the claim says is zero; proved when its numerator
/// is the zero polynomial. `reduction` says how the claim became this expression.
inline proof prove_zero(const std::string& reduction, const symbolic& difference) {
  proof p;
  p.proved = difference.is_zero();
  p.evidence["method"] = "exact";
  p.evidence["reduction"] = reduction;
  p.evidence["numerator_of_difference"] = to_string(difference.numerator(), "θ");
  p.evidence["result"] = p.proved ? "zero polynomial: identity proved" : "nonzero polynomial: identity false";
  return p;
}

/// Grid lemma over further variables (grid_lemma.hpp): `f(values)`, generic over the scalar, gives
/// the differences the claim says are zero (one, or a std::vector of several, each checked on its
/// own). Evaluated in our kernel at integer values 1, ..., bound + 1 of each variable (nonzero, so
/// divisions are defined); proved when they are zero at every point and the premise, computed in
/// GiNaC, holds: each is a polynomial of degree ≤ bound in each variable.
template <class F>
proof prove_zero_on_grid(const std::string& reduction, const std::vector<std::string>& variables,
                         const std::vector<int>& bounds, F&& f, run_memo* memo = nullptr) {
  std::size_t points = 0;
  symbolic witness;
  const auto first = first_nonzero_on_grid(bounds, [&](const std::vector<int>& point) {
    ++points;
    std::vector<symbolic> values;
    for (const int v : point) values.emplace_back(rational(v + 1));
    witness = symbolic(0);
    for (const symbolic& part : differences_of<symbolic>(f(values))) {
      if (!part.is_zero()) {
        witness = part;
        break;
      }
    }
    return witness;
  });
  proof p;
  p.evidence["method"] = "exact";
  p.evidence["reduction"] = reduction;
  std::string grid;
  for (std::size_t k = 0; k < variables.size(); ++k) {
    grid += (k ? ", " : "") + variables[k] + " in {1..." + std::to_string(bounds[k] + 1) + "} (degree <= " +
            std::to_string(bounds[k]) + ")";
  }
  p.evidence["grid"] = grid;
  p.evidence["points_evaluated"] = points;
  // The premise depends on the code of `f` alone (our kernel's transcription, never the paper's
  // text): computed once per run for each proof site (a claim judged again for a consequence or the
  // paper's earlier text reuses it), by the lambda's type and its reduction.
  std::string key = std::string("grid premise ") + typeid(F).name() + '\x1f' + reduction;
  for (std::size_t k = 0; k < variables.size(); ++k) key += '\x1f' + variables[k] + ' ' + std::to_string(bounds[k]);
  json premise = "not needed: the difference is not zero at a grid point";
  bool premise_holds = false;
  if (!first.has_value()) {
    std::tie(premise_holds, premise) = remembered<std::pair<bool, json>>(memo, key, [&] {
      json computed;
      const bool holds = grid_premise_holds(variables, bounds, f, computed);
      return std::make_pair(holds, computed);
    });
  }
  p.evidence["premise"] = premise;
  p.proved = !first.has_value() && premise_holds;
  if (!first.has_value()) {
    p.evidence["result"] = premise_holds ? "zero at every grid point: identity proved (grid lemma)"
                                         : "zero at every grid point, but the premise fails: nothing proved";
  } else {
    std::string at;
    for (std::size_t k = 0; k < first->size(); ++k) {
      at += (k ? ", " : "") + variables[k] + " = " + std::to_string((*first)[k] + 1);
    }
    p.evidence["result"] = "nonzero at " + at + ": identity false";
    p.evidence["numerator_there"] = to_string(witness.numerator(), "θ");
  }
  return p;
}

/// An identity over a finite set, checked at every member: `f(k)` for k = 0..last gives the
/// differences (one, or a std::vector of several) that must be zero. No premise: the set is the
/// whole of what the claim is about (e.g. the monomials t^k, k ≤ 6, of an expansion exact to degree 6).
template <class F>
proof prove_zero_at_each(const std::string& reduction, const std::string& variable, int last, F&& f) {
  proof p;
  p.evidence["method"] = "exact";
  p.evidence["reduction"] = reduction;
  p.evidence["checked"] = variable + " = 0.." + std::to_string(last) + ", every member of the set";
  for (int k = 0; k <= last; ++k) {
    for (const symbolic& part : differences_of<symbolic>(f(k))) {
      if (!part.is_zero()) {
        p.evidence["result"] = "nonzero at " + variable + " = " + std::to_string(k) + ": identity false";
        p.evidence["numerator_there"] = to_string(part.numerator(), "θ");
        return p;
      }
    }
  }
  p.proved = true;
  p.evidence["result"] = "zero at every member: identity proved";
  return p;
}

/// The same bound for every variable.
template <class F>
proof prove_zero_on_grid(const std::string& reduction, const std::vector<std::string>& variables, int bound, F&& f, run_memo* memo = nullptr) {
  return prove_zero_on_grid(reduction, variables, std::vector<int>(variables.size(), bound), std::forward<F>(f), memo);
}

/// Our kernel's evidence (its exact proof, with the numeric rechecks by enclosure where the check
/// has them): it holds when every method confirms, else it fails (errata are built explicitly).
/// decide() (decide.hpp) makes the verdict.
inline decider_evidence confirmed_if(bool ok, json evidence, std::string note = {}) {
  decider_evidence e;
  e.own = answer_of(ok);
  e.if_false = verdict::fails;
  e.found.evidence = std::move(evidence);
  e.found.note = std::move(note);
  return e;
}

/// An identity proved exactly and rechecked numerically.
inline decider_evidence identity(const proof& exact, bool numeric_within, json numeric, std::string note = {}) {
  json evidence = json::object();
  evidence["exact"] = exact.evidence;
  evidence["numeric"] = std::move(numeric);
  return confirmed_if(exact.proved && numeric_within, std::move(evidence), std::move(note));
}

/// An identity proved exactly, with no numeric recheck.
inline decider_evidence identity(const proof& exact, std::string note = {}) {
  json evidence = json::object();
  evidence["exact"] = exact.evidence;
  return confirmed_if(exact.proved, std::move(evidence), std::move(note));
}

/// An erratum: the printed form is refuted and the corrected form proved. When the printed form
/// turns out true, or the correction does not hold, it fails, and the evidence says which.
inline decider_evidence erratum(const proof& printed, const proof& corrected, std::string correction, std::string note = {}) {
  decider_evidence e;
  e.own = answer::fails;
  e.if_false = (!printed.proved && corrected.proved) ? verdict::erratum : verdict::fails;
  e.found.evidence["printed"] = printed.evidence;
  e.found.evidence["corrected"] = corrected.evidence;
  e.found.correction = std::move(correction);
  e.found.note = std::move(note);
  return e;
}

/// An erratum of a prose claim's words: the words quoted (in `evidence`) say other than what the
/// evidence computed, and the computed statement is the correction.
inline decider_evidence words_erratum(json evidence, std::string correction, std::string note = {}) {
  decider_evidence e;
  e.own = answer::fails;
  e.found.evidence = std::move(evidence);
  e.found.correction = std::move(correction);
  e.found.note = std::move(note);
  return e;
}

/// A finding with its one line, "printed X, should be Y" (words): decide() keeps it only where the
/// verdict is an erratum (or a remark is said).
inline decider_evidence amended(decider_evidence e, const std::string& where, const std::string& printed, const std::string& should_be) {
  e.found.amendments.push_back(amendment{where, printed, should_be, false});
  return e;
}

/// A verdict that a word of the quoted sentence decides (the computation beside it cannot move it):
/// said as such in the evidence ("lexical") and at the head of the note, so that it is not read as a
/// computed finding.
inline decider_evidence lexical(decider_evidence e, const std::string& word, const std::string& computed) {
  claim_result& r = e.found;
  r.evidence["lexical"] = "the verdict follows from the word '" + word + "' read in the quoted sentence; " + computed;
  r.note = "Lexical: decided by the word '" + word + "'; " + computed + "." + (r.note.empty() ? "" : " " + r.note);
  return e;
}

/// The numeric recheck of a check that lives beside its formula in the core:
/// `check(parameters, state)` returns its residual and round-off bound at each sampled case.
template <class Check>
json recheck_with(const run_context& ctx, const std::string& stream, Check&& check, bool& within) {
  return numeric_recheck(ctx, stream, [&](auto tag, const sample& s) {
    using Real = typename decltype(tag)::type;
    return check(oscillator_parameters<Real>{Real(s.m), Real(s.omega), Real(s.h)}, phase_point<Real>{Real(s.p), Real(s.q)});
  }, within);
}

/// V(q) = q^k and V'(q) = k q^(k−1): the basis of the quartic potentials on which the claims
/// stated for a general V are proved (each of them is linear in V).
struct monomial_potential {
  int k;
  template <class S>
  S operator()(const S& q) const { return power(q, k); }
  template <class S>
  S derivative(const S& q) const { return k == 0 ? S(0) : S(k) * power(q, k - 1); }
  template <class S>
  static S power(const S& q, int n) {
    S v(1);
    for (int i = 0; i < n; ++i) v = v * q;
    return v;
  }
};

}  // namespace simpson::verify::detail
