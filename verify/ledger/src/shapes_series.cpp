// The series shapes (shape_support.hpp): a printed truncation error, and the order a sentence states.

#include "shape_support.hpp"

#include "printed_check_support.hpp"

#include <simpson/verify/quoted_words.hpp>

#include <fmt/format.h>

#include <optional>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// The scheme (= 0, in three consecutive states) on the exact solution of q'' = −ω² q through the
/// middle state, q(t_j ± h) = q_j cos ωh ± (v_j/ω) sin ωh, as GiNaC's series in h to O(h^order):
/// cos and sin as Taylor polynomials through h^(order + 2), the scheme dividing by h² at most.
ex series_on_solution(const ex& scheme, const std::vector<GiNaC::symbol>& sequence, const GiNaC::symbol& h, const ex& omega, int order) {
  const GiNaC::symbol velocity("v_j");
  ex c = 0, sn = 0, term = 1;
  for (int k = 0; k <= order + 2; ++k) {
    if (k > 0) term = term * omega * h / k;
    if (k % 2 == 0) c += (k % 4 == 0 ? 1 : -1) * term;
    else sn += (k % 4 == 1 ? 1 : -1) * term;
  }
  const ex shift = velocity / omega * sn;
  const ex on_solution = scheme.subs(GiNaC::lst{sequence[0] == sequence[1] * c - shift, sequence[2] == sequence[1] * c + shift});
  return GiNaC::expand(GiNaC::series_to_poly(GiNaC::series(on_solution, h == 0, order)));
}

/// The lowest power of h with a nonzero coefficient, or nothing.
std::optional<int> lowest_power(const ex& e, const GiNaC::symbol& h) {
  const ex expanded = GiNaC::expand(e);
  for (int k = expanded.ldegree(h); k <= expanded.degree(h); ++k) {
    if (!GiNaC::normal(expanded.coeff(h, k)).is_zero()) return k;
  }
  return std::nullopt;
}

}  // namespace

/// A printed truncation error: the scheme (an expression in three consecutive states, = 0) on the
/// exact solution of q'' = −ω² q through the middle state, q(t_j ± h) = q_j cos ωh ± (v_j/ω) sin ωh,
/// as GiNaC's series in h, against the printed terms and order O(h^N).
claim_result truncation_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex printed = read.formula("printed");
  const ex scheme = read.formula("scheme");
  const ex omega = read.formula("frequency");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence"), step = read.symbols("step");
  const GiNaC::symbol& h = step.front();
  claim_result result;
  result.printed = read.printed();
  result.certificate_missing = "a series in h to an order: no Coq statement for this shape yet";
  // The printed terms and its order term O(h^N).
  const auto [terms, order] = split_order(printed, h);
  if (order <= 0) throw std::invalid_argument(reference_of(call, "printed") + " has no order term O(" + h.get_name() + "^k)");
  const ex series = series_on_solution(scheme, sequence, h, omega, order);
  const ex gap = GiNaC::normal(series - terms);
  const std::string what = fmt::format("({}) on the exact solution = ({}) + O({}^{})", reference_of(call, "scheme"), reference_of(call, "printed"),
                                       h.get_name(), order);
  const int lowest = lowest_power(series, h).value_or(-1);  // the series' first nonzero power
  result.evidence["exact"] = {{"statement", what},
                              {"series", text_of(series) + " + O(" + h.get_name() + "^" + std::to_string(order) + ")"},
                              {"leading_power", lowest},
                              {"ginac", gap.is_zero() ? "holds: series − printed terms = 0 through the printed order"
                                                      : "fails: series − printed terms = " + text_of(gap)},
                              {"own", "not applicable: a series (GiNaC's alone)"}};
  if (gap.is_zero()) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = "as derived: " + text_of(series) + " + O(" + h.get_name() + "^" + std::to_string(order) + ")";
  result.note = "As printed: " + what + " is false; the series differs by " + text_of(gap) + ".";
  return result;
}

/// The order a sentence states ("the scheme is of {order} order"), its words quoted from the
/// document and parsed, against the order computed: the scheme on the exact solution of
/// q'' = −ω² q is O(h^(p + s + 2)) when its q_{j+1} coefficient is of order h^s, so p = that power − s − 2.
claim_result stated_order_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  const ex scheme = read.formula("scheme");
  const ex omega = read.formula("frequency");
  const std::vector<GiNaC::symbol> sequence = read.symbols("sequence"), step = read.symbols("step");
  const GiNaC::symbol& h = step.front();
  const quoted_sentence sentence = quote(ctx, call.with.at("sentence").values.front());
  const int stated = sentence.number("order");
  claim_result result;
  result.printed = read.printed();
  result.certificate_missing = "an order of accuracy: a statement about a series, no Coq statement for this shape yet";
  const std::optional<int> scale = lowest_power(GiNaC::expand(GiNaC::normal(scheme)).coeff(sequence[2], 1), h);
  constexpr int series_order = 10;
  const ex series = series_on_solution(scheme, sequence, h, omega, series_order);
  const std::optional<int> leading = lowest_power(series, h);
  if (!scale) throw std::invalid_argument(reference_of(call, "scheme") + " has no " + sequence[2].get_name() + " term");
  result.evidence["exact"] = {{"statement", "the order the sentence states, against the order computed"},
                              {"stated", stated},
                              {"series", text_of(series) + " + O(" + h.get_name() + "^" + std::to_string(series_order) + ")"},
                              {"q_next_coefficient_power", *scale}};
  if (!leading) {
    result.outcome = verdict::undecided;
    result.note = "The series vanishes through O(h^" + std::to_string(series_order) + "): the order is at least " +
                  std::to_string(series_order - *scale - 2) + ", beyond what the shape expands.";
    return result;
  }
  const int order = *leading - *scale - 2;
  result.evidence["exact"]["computed"] = order;
  if (order == stated) {
    result.outcome = verdict::holds;
    return result;
  }
  result.outcome = verdict::erratum;
  result.correction = fmt::format("the scheme is of order {}", order);
  result.note = fmt::format("As printed: the sentence states order {}; on the exact solution the scheme is {} + O(h^{}).", stated,
                            text_of(series), series_order);
  return result;
}

}  // namespace simpson::verify::detail
