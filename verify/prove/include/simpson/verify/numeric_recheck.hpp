#pragma once
// Numeric rechecks at random inputs. The verdict is an enclosure's (enclosure_decision.hpp): the
// residual in interval arithmetic from the exact inputs, the digits doubled until it decides. The
// ladder measures the residual in every floating precision of the run against its round-off bound
// k·eps·condition, and shows it falling with the precision; it no longer decides.

#include <simpson/precision.hpp>
#include <simpson/residual.hpp>
#include <simpson/verify/claim.hpp>
#include <simpson/verify/enclosure_decision.hpp>
#include <simpson/verify/interruption.hpp>

#include <boost/multiprecision/cpp_bin_float.hpp>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>

namespace simpson::verify {

/// splitmix64: a small, fully specified generator, so that samples are the same on every
/// platform and standard library (std::uniform_real_distribution is not).
class sample_generator {
 public:
  sample_generator(std::uint64_t seed, const std::string& stream) : state_(seed) {
    for (const char c : stream) state_ = (state_ ^ static_cast<unsigned char>(c)) * 0x100000001b3ULL;  // FNV-1a
  }
  std::uint64_t next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  /// Uniform in [0, 1), 53 random bits: exactly representable in every precision.
  double unit() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * unit(); }
  /// Log-uniform in [lo, hi].
  double log_uniform(double lo, double hi) { return std::exp(uniform(std::log(lo), std::log(hi))); }

 private:
  std::uint64_t state_;
};

/// Inputs of one numeric sample, as doubles: exact in every precision, so a residual measures
/// only the round-off of the formulas.
struct sample {
  double m, omega, h, p, q;
};

/// The sample's inputs, exactly (doubles to 17 digits).
inline std::string fmt_sample(const sample& s) {
  return "m = " + simpson::to_string(s.m) + ", omega = " + simpson::to_string(s.omega) + ", h = " + simpson::to_string(s.h) +
         ", p = " + simpson::to_string(s.p) + ", q = " + simpson::to_string(s.q);
}

/// m log-uniform in [1e-3, 1e3], ω in [1e-2, 1e3], ωh log-uniform in [1e-3, 2.7] (inside the
/// first stable band ωh < 2√2 ≈ 2.83), q uniform in [−1, 1], p uniform in mω·[−1, 1].
inline sample draw_sample(sample_generator& g) {
  sample s{};
  s.m = g.log_uniform(1e-3, 1e3);
  s.omega = g.log_uniform(1e-2, 1e3);
  s.h = g.log_uniform(1e-3, 2.7) / s.omega;
  s.q = g.uniform(-1, 1);
  s.p = s.m * s.omega * g.uniform(-1, 1);
  return s;
}


namespace detail {
template <class Real>
double log10_or_floor(const Real& v) {
  if (v == 0) return -1e9;
  if constexpr (is_exact_v<Real>) {
    return 0;  // a nonzero exact residual: the identity is false
  } else {
    using std::abs;
    using std::log10;
    return static_cast<double>(boost::multiprecision::cpp_bin_float_50(log10(Real(abs(v)))));
  }
}
}  // namespace detail

/// What an enclosure is judged against, in words: "a width of at most 1.2e-30" for an identity,
/// "the bound 3.76e-21" for a bound (its upper end, to 3 digits).
inline std::string judged_text(const residual_and_bound<interval>& r) {
  const std::string scale = simpson::to_string(boost::multiprecision::mpfr_float(upper(judged_scale(r))), 3);
  return r.zero_claimed ? "0, the width at most " + scale : "the bound " + scale;
}

/// The enclosure rung: `check` at each sample in intervals of ctx.enclosure_digits, doubled for a
/// sample until decide() decides it, at most to ctx.enclosure_budget_digits (then throws
/// enclosure_undecided naming the sample and the enclosure). Sets `holds` to false when an
/// enclosure proves the claim false at some sample.
template <class Check>
json enclosure_rung(const run_context& ctx, const std::string& stream, Check&& check, bool& holds) {
  sample_generator g(ctx.seed, stream);
  holds = true;
  unsigned highest = ctx.enclosure_digits;
  bool zero_claimed = true;
  boost::multiprecision::mpfr_float widest_relative = -1;
  std::string widest_text, refuted;
  for (unsigned k = 0; k < ctx.samples; ++k) {
    throw_if_interrupted();
    const sample s = draw_sample(g);
    for (unsigned digits = ctx.enclosure_digits;; digits *= 2) {
      const scoped_interval_digits scope(digits);
      const residual_and_bound<interval> r = check(precision_tag<interval>{}, s);
      zero_claimed = r.zero_claimed;
      const enclosure_outcome outcome = decide(r);
      if (outcome == enclosure_outcome::undecided && digits * 2 <= ctx.enclosure_budget_digits) continue;
      if (outcome == enclosure_outcome::undecided) {
        throw enclosure_undecided(stream + ": at " + fmt_sample(s) + " the residual's enclosure " + enclosure_text(r.residual) +
                                  " against " + judged_text(r) + " decides nothing at " + std::to_string(digits) +
                                  " digits, the run's budget");
      }
      if (digits > highest) highest = digits;
      // The width relative to the scale the claim is judged at.
      const boost::multiprecision::mpfr_float scale = upper(judged_scale(r));
      const boost::multiprecision::mpfr_float relative =
          scale > 0 ? boost::multiprecision::mpfr_float(width(r.residual) / scale) : boost::multiprecision::mpfr_float(0);
      if (relative > widest_relative) {
        widest_relative = relative;
        widest_text = enclosure_text(r.residual) + " against " + judged_text(r) + " (" + std::to_string(digits) + " digits)";
      }
      if (outcome == enclosure_outcome::fails && refuted.empty()) {
        holds = false;
        refuted = "at " + fmt_sample(s) + ": residual " + enclosure_text(r.residual) + " against " + judged_text(r) + " (" +
                  std::to_string(digits) + " digits)";
      }
      break;
    }
  }
  json out = json::object();
  out["method"] = "interval arithmetic (MPFI), outward rounding from the exact sample inputs: the exact residual is inside";
  out["rule"] = enclosure_rule(zero_claimed);
  out["samples"] = ctx.samples;
  out["first_digits"] = ctx.enclosure_digits;
  out["decided_at_digits"] = highest;
  out["budget_digits"] = ctx.enclosure_budget_digits;
  out["widest_enclosure"] = widest_text;
  out["decision"] = holds ? "holds" : "fails";
  if (!refuted.empty()) out["refuted"] = refuted;
  return out;
}

/// Runs `check(tag, sample)` (returning residual_and_bound<Real>) on ctx.samples samples in each
/// precision of ctx; with AllowExact false (checks that need cos or sin) exact precisions are
/// listed as skipped. Evidence: per precision the largest residual, its bound, the largest
/// residual/bound ratio and whether every sample was within its bound; whether the largest
/// residuals fall along the ladder; and the enclosure rung. Sets `within` to what decides: the
/// enclosures (and an exact rung's residual, which must be 0); the ladder measures.
template <bool AllowExact = true, class Check>
json numeric_recheck(const run_context& ctx, const std::string& stream, Check&& check, bool& within) {
  json rungs = json::array();
  bool exact_zero = true;
  double previous_log10 = 1e9;
  bool falls = true;
  std::string diagnosis;
  for (const precision& prec : ctx.precisions) {
    sample_generator g(ctx.seed, stream);
    json rung = prec.visit([&](auto tag) {
      using Real = typename decltype(tag)::type;
      if constexpr (!AllowExact && is_exact_v<Real>) {
        return json{{"precision", prec.name()}, {"skipped", "needs cos and sin"}, {"within_bound", true},
                    {"log10_normalised_residual", -1e9}};
      } else {
      Real largest_residual = 0, bound_at_worst = 0;
      double worst_ratio = 0;
      bool all_within = true;
      for (unsigned k = 0; k < ctx.samples; ++k) {
        throw_if_interrupted();
        const sample s = draw_sample(g);
        const residual_and_bound<Real> r = check(tag, s);
        using std::abs;
        const Real residual = abs(r.residual);
        const bool ok = is_exact_v<Real> ? residual == 0 : residual <= r.bound;
        all_within = all_within && ok;
        if (residual > largest_residual) largest_residual = residual;
        double ratio = 0;
        if (residual != 0) {
          ratio = r.bound == 0 ? HUGE_VAL
                               : static_cast<double>(boost::multiprecision::cpp_bin_float_50(Real(residual / r.bound)));
        }
        if (k == 0 || ratio > worst_ratio) {
          worst_ratio = ratio;
          bound_at_worst = r.bound;
        }
      }
      json out = json::object();
      out["precision"] = prec.name();
      out["epsilon"] = prec.epsilon();
      out["samples"] = ctx.samples;
      out["max_residual"] = is_exact_v<Real> ? std::string(largest_residual == 0 ? "0" : simpson::to_string(largest_residual))
                                            : simpson::to_string(largest_residual, 3);
      out["max_residual_over_bound"] = simpson::to_string(worst_ratio, 3);
      out["bound_at_that_sample"] = is_exact_v<Real> ? std::string("0 (exact)") : simpson::to_string(bound_at_worst, 3);
      out["within_bound"] = all_within;
      // The residual in units of the condition factor, ~ ratio × eps: what must fall along the ladder.
      double normalised = -1e9;
      if constexpr (!is_exact_v<Real>) {
        if (worst_ratio > 0) normalised = std::log10(worst_ratio) + detail::log10_or_floor(eps<Real>());
      }
      out["log10_normalised_residual"] = normalised;
      return out;
      }
    });
    const double log10_residual = rung["log10_normalised_residual"].get<double>();
    if (log10_residual > previous_log10 + 0.5) falls = false;
    if (log10_residual > -1e8) previous_log10 = log10_residual;
    if (prec.exact() && !rung["within_bound"].get<bool>()) exact_zero = false;
    if (!rung["within_bound"].get<bool>()) {
      if (prec.digits10() > 20 && log10_residual > -19) {  // within ~3 decades of double epsilon
        diagnosis = "residual in " + prec.name() +
                    " is stuck near double round-off: a double has leaked into generic code";
      }
    }
    rung.erase("log10_normalised_residual");
    rungs.push_back(std::move(rung));
  }
  json out = json::object();
  out["inputs"] = "m in [1e-3, 1e3], omega in [1e-2, 1e3], omega h in [1e-3, 2.7] (log-uniform); q in [-1, 1], p in m omega [-1, 1]";
  out["ladder"] = std::move(rungs);
  out["residuals_fall_with_precision"] = falls;
  out["falls_means"] = "max residual/bound times epsilon (the residual in units of its condition factor) does not rise along the ladder";
  if (!diagnosis.empty()) out["diagnosis"] = diagnosis;
  bool enclosed_holds = false;
  out["enclosure"] = enclosure_rung(ctx, stream, check, enclosed_holds);
  within = enclosed_holds && exact_zero;
  out["decided_by"] = "the enclosures (and an exact rung's residual, which must be 0); the ladder measures";
  return out;
}

}  // namespace simpson::verify
