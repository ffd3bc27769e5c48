// The sum shape (shape_support.hpp): the range of a printed sum over the elements of a printed
// interval, from the printed times of its nodes.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/tex_math.hpp>

#include <fmt/format.h>

#include <regex>

namespace simpson::verify::detail {

using GiNaC::ex;

namespace {

/// The offset k of a node x_{j+k} from the index j; throws std::invalid_argument when the name is not one.
GiNaC::numeric offset_of(const std::string& name, const std::string& index) {
  const std::optional<GiNaC::numeric> k = index_offset(name, index);
  if (!k) throw std::invalid_argument("'" + name + "' is not a node x_" + index + ", x_" + index + "+1, ... of the sum's index");
  return *k;
}

/// The index at which `time` (a function of j, linear) equals `at`; throws when there is none.
ex index_where(const ex& time, const GiNaC::symbol& j, const ex& at, const std::string& what) {
  const ex slope = GiNaC::normal(GiNaC::diff(time, j));
  if (slope.is_zero() || GiNaC::normal(GiNaC::diff(slope, j)) != 0) throw std::invalid_argument(what + " is not linear in the index " + j.get_name());
  return GiNaC::normal((at - time.subs(j == 0)) / slope);
}

}  // namespace

/// A printed sum over the elements of a printed interval a <= t <= b: its element j runs from the
/// node x_{j+k0} to x_{j+k1} (`element`), at the printed times t_j (`node`, a function of j); the
/// first element starts at a and the last ends at b, so the index runs from the j with t_{j+k0} = a
/// to the j with t_{j+k1} = b (GiNaC solves both; our kernel checks each end, and each printed bound
/// against it).
decider_evidence sum_range_shape(const shape_call& call, const run_context& ctx) {
  shape_reader read(call, document_of(ctx));
  // The bounds as printed in the sum, or as a sentence states them ("j running from $1$ to $N$").
  GiNaC::symbol j;
  ex lower, upper;
  const bool in_words = read.has("sentence");
  if (in_words) {
    const quoted_sentence said = quote(ctx, call.with.at("sentence").values.front());
    j = symbol_named(call.with.at("index").values.front());
    const auto bound = [&](const std::string& hole) {
      try {
        const ex value = read_tex(said.words(hole), read.reading(), paper_symbols());
        said.record(hole, text_of(value));
        return value;
      } catch (const tex_error&) {
        said.unparsed(hole, "a bound written as TeX ($1$, $N - 1$)");
      }
    };
    lower = bound("from");
    upper = bound("to");
  } else {
    const ex sum = read.formula("sum");
    if (!is_sum(sum)) throw std::invalid_argument(reference_of(call, "sum") + " is not a sum \\sum_{j=a}^{b}");
    j = GiNaC::ex_to<GiNaC::symbol>(sum.op(1));
    lower = sum.op(2);
    upper = sum.op(3);
  }
  const std::vector<GiNaC::symbol> element = read.symbols("element");
  const GiNaC::numeric k0 = offset_of(element.front().get_name(), j.get_name()), k1 = offset_of(element.back().get_name(), j.get_name());
  const ex time = read.formula("node");
  if (!time.has(j)) throw std::invalid_argument(reference_of(call, "node") + " is not a function of the sum's index " + j.get_name());
  const std::vector<ex> range = read.sides(read.raw("range"));
  const ex starts = time.subs(j == j + k0), ends = time.subs(j == j + k1);
  const ex first = index_where(starts, j, range.front(), reference_of(call, "node"));
  const ex last = index_where(ends, j, range.back(), reference_of(call, "node"));
  const bool ginac_holds = GiNaC::normal(lower - first).is_zero() && GiNaC::normal(upper - last).is_zero();
  // Our kernel: the derived bounds put the ends where the interval's are, and each printed bound is
  // or is not the derived one, as GiNaC found.
  const kernel_decision at_start = kernel_decides_zero(starts.subs(j == first) - range.front());
  const kernel_decision at_end = kernel_decides_zero(ends.subs(j == last) - range.back());
  const kernel_decision low = kernel_decides_zero(lower - first), high = kernel_decides_zero(upper - last);
  const bool own_decided = at_start.outcome == kernel_decision::result::zero && at_end.outcome == kernel_decision::result::zero &&
                           low.outcome != kernel_decision::result::not_applicable && high.outcome != kernel_decision::result::not_applicable;
  const bool own_holds = low.outcome == kernel_decision::result::zero && high.outcome == kernel_decision::result::zero;
  const std::string j_name = j.get_name();
  const std::string derived = fmt::format("{} = {}, ..., {}: {} terms", j_name, text_of(first), text_of(last), text_of(GiNaC::normal(last - first + 1)));
  claim_result result;
  result.printed = read.printed();
  result.evidence["exact"] = {
      {"statement", fmt::format("the range of ({}) over the elements of ({}), the nodes at ({})", in_words ? "the sum the sentence states" : reference_of(call, "sum"), reference_of(call, "range"),
                                reference_of(call, "node"))},
      {"printed", fmt::format("{} = {}, ..., {}: {} terms", j_name, text_of(lower), text_of(upper), text_of(GiNaC::normal(upper - lower + 1)))},
      {"derived", fmt::format("element {} from t = {} to t = {}; the first starts at {}, the last ends at {}: {}", j_name, text_of(starts), text_of(ends),
                              text_of(range.front()), text_of(range.back()), derived)},
      {"ginac", fmt::format("holds: the bounds solved from the nodes' times (normal form): {}; the printed ones {}", derived,
                            ginac_holds ? "are these" : "differ")},
      {"own", !own_decided ? "not applicable: " + at_start.evidence + "; " + at_end.evidence + "; " + low.evidence + "; " + high.evidence
                           : "holds: the derived ends at the interval's (" + at_start.evidence + "; " + at_end.evidence +
                                 "), the printed bounds against them (" + low.evidence + "; " + high.evidence + "): they " +
                                 (own_holds ? "are these" : "differ")}};
  // The correction: the printed TeX with the derived bounds: "S_d = \\sum_{j=0}^{N-1} L_d (q_j ,\\, q_{j+1} )"; or,
  // for bounds stated in words, the words as they should be.
  std::string corrected;
  if (in_words) {
    corrected = fmt::format("{} runs from {} to {}, not from {} to {}", j_name, text_of(first), text_of(last), text_of(lower), text_of(upper));
  } else {
    const referenced_formula printed = read.raw("sum");
    corrected = std::regex_replace(folded_space(printed.sides.back()), std::regex(R"(\\sum_\{[^{}]*\}\^(\{[^{}]*\}|\S))"),
                                   fmt::format("\\sum_{{{}={}}}^{{{}}}", j_name, text_of(first), text_of(last)),
                                   std::regex_constants::format_first_only);  // no $ in the replacement
    if (printed.sides.size() > 1) corrected = folded_space(printed.sides.front()) + " = " + corrected;
  }
  if (!ginac_holds) {
    result.note = fmt::format("As printed: {} = {}, ..., {}, {} terms.", j_name, text_of(lower), text_of(upper), text_of(GiNaC::normal(upper - lower + 1)));
    const auto range_tex = [&](const ex& a, const ex& b) {
      return fmt::format("\\sum_{{{}={}}}^{{{}}}", canonical_tex(j), canonical_tex(a), canonical_tex(b));
    };
    result.amendments.push_back(in_words ? amendment_in_words("the range the sentence states", fmt::format("{} = {}, ..., {}", j_name, text_of(lower), text_of(upper)),
                                                              fmt::format("{} = {}, ..., {}", j_name, text_of(first), text_of(last)))
                                         : amendment{"the sum's range", range_tex(lower, upper), range_tex(first, last)});
  }
  return settled(std::move(result), answer_of(ginac_holds), own_decided ? answer_of(own_holds) : answer::none, "the range",
                 fmt::format("{}: the elements of [{}, {}] are {}", corrected, text_of(range.front()), text_of(range.back()), derived));
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> sums_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"sum-range", "the printed sum runs over the elements of the printed interval, from the first (starting at its start) to the last (ending at its end)", "sum",
       with_where({{"sum", argument_kind::formula, false, "the printed sum \\sum_{j=a}^{b}", 0, "", false, {}, "", "sentence"},
                   pattern_with_hole("sentence", "instead of a printed sum: a sentence stating its range, with the holes {from} and {to} (TeX: '$1$', '$N - 1$')",
                                     "from", false),
                   {"index", argument_kind::word, false, "the sum's index, with a sentence: 'j'", 0, "", false, {}, "", "", "sentence"},
                   {"element", argument_kind::symbols, true, "the summand's first and last nodes, x_j and x_{j+1}", 2},
                   {"node", argument_kind::formula, true, "the printed time of node j, t_j = j h"},
                   {"range", argument_kind::condition, true, "the printed interval a <= t <= b"}}),
       sum_range_shape});
  return all;
}

}  // namespace simpson::verify::detail
