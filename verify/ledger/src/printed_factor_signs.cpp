#include "printed_factor_signs.hpp"

#include "printed_check_support.hpp"

#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <simpson/three_term_scheme.hpp>

#include <algorithm>

namespace simpson::verify::detail {
namespace {

using GiNaC::ex;

/// F(x) with f = F(ω²h²), or nothing when f is not a function of ω²h² alone.
std::optional<ex> as_function_of_x(const ex& f, const GiNaC::symbol& x) {
  const ex omega = sym("omega"), h = sym("h");
  const ex at_unit = GiNaC::expand(f.subs(omega == 1));
  const int top = at_unit.degree(h);
  ex F = 0;
  for (int k = 0; k <= top; ++k) {
    const ex c = at_unit.coeff(h, k);
    if (k % 2 == 1) {
      if (!GiNaC::normal(c).is_zero()) return std::nullopt;
      continue;
    }
    F += c * GiNaC::pow(x, k / 2);
  }
  if (!F.info(GiNaC::info_flags::rational_polynomial) && !GiNaC::is_a<GiNaC::numeric>(F)) return std::nullopt;
  if (!GiNaC::normal(F.subs(x == GiNaC::pow(omega * h, 2)) - f).is_zero()) return std::nullopt;
  return F;
}

/// The sign of F on 0 < x < band_end, decided by the coefficients of the numerator in t.
printed_factor_sign sign_on_band(const ex& F, const GiNaC::symbol& x, const printed_stability_band& band) {
  printed_factor_sign s;
  const GiNaC::symbol t("t");
  const int deg = F.degree(x);
  const GiNaC::numeric band_end(band.numerator, band.denominator);
  const ex N = GiNaC::expand(GiNaC::normal(F.subs(x == band_end * t / (1 + t)) * GiNaC::pow(1 + t, deg)));
  bool positive = true, negative = true, nonzero = false;
  for (int k = 0; k <= N.degree(t); ++k) {
    const ex c = N.coeff(t, k);
    if (!GiNaC::is_a<GiNaC::numeric>(c)) {
      positive = negative = false;
      break;
    }
    const GiNaC::numeric n = GiNaC::ex_to<GiNaC::numeric>(c);
    if (n.is_zero()) continue;
    nonzero = true;
    positive = positive && n.is_positive();
    negative = negative && n.is_negative();
  }
  s.sign = !nonzero ? 0 : positive ? 1 : negative ? -1 : 0;
  s.proof = "x = " + text_of(band_end) + " t/(1 + t), t > 0: (1 + t)^" + std::to_string(deg) + " F = " + text_of(N) +
            (s.sign == 0  ? ", coefficients of both signs: no sign proved"
             : s.sign > 0 ? ", every coefficient >= 0: positive"
                          : ", every coefficient <= 0: negative");
  return s;
}

printed_factor_sign decided_sign(const ex& f, bool is_prefactor, const printed_stability_band& band_end) {
  const GiNaC::symbol x("x");
  const std::optional<ex> F = as_function_of_x(f, x);
  printed_factor_sign s;
  if (F) {
    s = sign_on_band(*F, x, band_end);
  } else {
    s.proof = "not a polynomial in omega^2 h^2 alone: no sign proved";
  }
  s.factor = text_of(f);
  s.prefactor = is_prefactor;
  return s;
}

}  // namespace

std::string printed_stability_band::text() const {
  const std::string end = denominator == 1 ? std::to_string(numerator) : std::to_string(numerator) + "/" + std::to_string(denominator);
  return "0 < omega^2 h^2 < " + end + " ((stabilite) as printed: 0 < omega h < " + bound + ")";
}

printed_stability_band read_stability_band(const paper_reading& paper) {
  const ex lower = printed_side(paper, "stabilite", 0), middle = printed_side(paper, "stabilite", 1), upper = printed_side(paper, "stabilite", 2);
  const ex square = GiNaC::normal(GiNaC::pow(upper, 2));
  const bool form = GiNaC::normal(lower).is_zero() && GiNaC::normal(middle - sym("omega") * sym("h")).is_zero();
  if (!form || !GiNaC::is_a<GiNaC::numeric>(square) || !GiNaC::ex_to<GiNaC::numeric>(square).is_rational() ||
      !GiNaC::ex_to<GiNaC::numeric>(square).is_positive()) {
    throw text_changed("(stabilite) reads " + text_of(lower) + " < " + text_of(middle) + " < " + text_of(upper) +
                       ", not 0 < omega h < U with U^2 a positive rational: the band a claim judges under it is not read");
  }
  const GiNaC::numeric q = GiNaC::ex_to<GiNaC::numeric>(square);
  printed_stability_band band;
  band.numerator = q.numer().to_long();
  band.denominator = q.denom().to_long();
  band.bound = text_of(upper);
  return band;
}

std::vector<printed_factor_sign> core_discriminant_factor_signs(const printed_stability_band& band_end) {
  std::vector<printed_factor_sign> signs;
  const auto factors = discriminant_factors<ex>(GiNaC::pow(sym("omega") * sym("h"), 2));
  for (std::size_t k = 0; k < factors.size(); ++k) signs.push_back(decided_sign(factors[k], k == 0, band_end));
  return signs;
}

std::vector<printed_factor_sign> printed_discriminant_factor_signs(const paper_reading& paper, const printed_stability_band& band_end) {
  const ex printed = paper.at("discriminant-factorized").value;
  std::vector<ex> binomials;
  ex prefactor = 1;
  if (GiNaC::is_a<GiNaC::mul>(printed)) {
    for (std::size_t k = 0; k < printed.nops(); ++k) {
      const ex f = printed.op(k);
      if (GiNaC::is_a<GiNaC::add>(f)) {
        binomials.push_back(f);
      } else {
        prefactor *= f;
      }
    }
  } else {
    binomials.push_back(printed);
  }
  // GiNaC orders a product's factors by hash, which differs from process to process: by text instead.
  std::sort(binomials.begin(), binomials.end(), [](const ex& a, const ex& b) { return text_of(a) < text_of(b); });
  std::vector<printed_factor_sign> signs;
  if (!GiNaC::is_a<GiNaC::numeric>(prefactor) || prefactor != 1) signs.push_back(decided_sign(prefactor, true, band_end));
  for (const ex& f : binomials) signs.push_back(decided_sign(f, false, band_end));
  return signs;
}

}  // namespace simpson::verify::detail
