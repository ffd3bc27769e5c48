// Section 8's Figure 1: the caption's statements, about a figure whose data the source does not carry.

#include "bespoke_checks.hpp"
#include "claim_support.hpp"

#include <simpson/verify/enclosure_undecided.hpp>
#include <simpson/verify/paper_table.hpp>
#include <simpson/verify/quoted_words.hpp>
#include <simpson/verify/table1_enclosed.hpp>

#include <boost/math/constants/constants.hpp>

#include <fmt/format.h>

#include <regex>
#include <string>
#include <utility>
#include <vector>

namespace simpson::verify::detail {
namespace {

/// Figure 1 (N = 15, one period, q = sin omega t, p = m omega cos omega t, the momentum rescaled by
/// m omega): the caption's two statements, each scheme examined. The words are qualitative; the
/// reading is stated and computed: "very close" = within 1/500 of the amplitude (a pixel of a
/// 500-pixel panel: the curves cannot be told apart); "very satisfactory" = within 1/10 of the
/// amplitude (the curve follows the exact one, visibly).
decider_evidence check_figure1(const run_context& ctx) {
  const quoted_sentence said = quote(ctx, "Both schemes give very {quality} results. Observe that the momentum $ \\, p \\, $ is "
                                          "very close to the exact solution with the {scheme} scheme.");
  said.choice("quality", {{"satisfactory", "within 1/10 of the amplitude"}, {"good", "within 1/10 of the amplitude"}});
  const std::string close_one = said.choice("scheme", {{"symplectic Simpson", "symplectic Simpson"}, {"Simpson", "symplectic Simpson"},
                                                       {"Newmark", "Newmark"}});
  // The reading's bounds, exactly: 1/10 and 1/500 of the amplitude (1 for q, m omega for p).
  const std::vector<std::pair<long, long>> bounds{{1, 10}, {1, 500}};
  const double amplitude = boost::math::constants::two_pi<double>();  // m omega with m = 1
  json schemes = json::array();
  bool both_satisfactory = true, named_close = false;
  std::string undecided;
  for (const bool simpson_scheme : {false, true}) {
    const std::string name = simpson_scheme ? "symplectic Simpson" : "Newmark";
    // Decided by the exact scheme's errors enclosed; the double run (the paper's) shown beside.
    const bounded_errors enclosed = enclosed_errors_within(simpson_scheme, 15, bounds, table1_enclosure_digits);
    const bound_decision satisfactory = enclosed.worst_within[0], close = enclosed.p_within[1];
    for (const bound_decision d : {satisfactory, close}) {
      if (d == bound_decision::undecided) undecided += (undecided.empty() ? "" : "; ") + name;
    }
    both_satisfactory = both_satisfactory && satisfactory == bound_decision::at_most;
    if (name == close_one) named_close = close == bound_decision::at_most;
    const table_errors e = run_table_experiment(simpson_scheme, 15);
    schemes.push_back({{"scheme", name},
                       {"p_error_over_m_omega", enclosed.p_over_m_omega},
                       {"q_error", enclosed.q},
                       {"in_double", {{"p_error_over_m_omega", fmt::format("{:.2e}", e.p / amplitude)},
                                      {"q_error", fmt::format("{:.2e}", e.q)}}},
                       {"very_satisfactory", satisfactory == bound_decision::at_most},
                       {"momentum_very_close", close == bound_decision::at_most}});
  }
  if (!undecided.empty()) {
    throw enclosure_undecided("figure1-statements: an error's enclosure straddles 1/10 or 1/500 at " +
                              std::to_string(table1_enclosure_digits) + " digits (" + undecided + ")");
  }
  json evidence;
  evidence["numeric"] = {{"method", "enclosures (MPFI, " + std::to_string(table1_enclosure_digits) +
                                        " digits, pi enclosed) of the exact schemes' errors, compared with 1/10 and 1/500 "
                                        "exactly; the double run shown beside"},
                         {"experiment", "Section 8 conventions, N = 15 (Figure 1), errors at the nodes over one period"},
                         {"schemes", schemes},
                         {"reading", "very satisfactory: max error <= 1/10 of the amplitude; very close: <= 1/500"}};
  // The figure the caption describes, as the source includes it: the last \includegraphics before
  // the quoted caption sentence (found by the quote itself, not by a typed anchor).
  const std::string& text = paper_of(ctx).source.text;
  std::size_t sentence_at = 0;
  for (int line = 1; line < said.span().line && sentence_at != std::string::npos; ++line) {
    sentence_at = text.find('\n', sentence_at);
    if (sentence_at != std::string::npos) ++sentence_at;
  }
  std::string included;
  bool found = false;
  if (sentence_at != std::string::npos) {
    static const std::regex graphics(R"(\\includegraphics(\[[^\]]*\])?\{([^}]*)\})");
    const std::string before = text.substr(0, sentence_at);
    for (auto it = std::sregex_iterator(before.begin(), before.end(), graphics); it != std::sregex_iterator(); ++it) {
      included = folded_space((*it)[2].str());
      found = true;
    }
  }
  evidence["figure"] = {{"includegraphics", found ? included : "none before the caption"}, {"present", found && !included.empty()}};
  // The harness reads no figure's data: the caption's statements are unverifiable whatever file
  // \includegraphics names; the errors above are context, not proof.
  // Whether the figure's data is in the source is read, not computed: it is not, so the caption's
  // statements are unverifiable.
  decider_evidence judged;
  judged.statement = "the figure's data is in the source";
  judged.lexical = answer::fails;
  judged.if_false = verdict::unverifiable;
  claim_result& r = judged.found;
  r.evidence = evidence;
  r.note = (found && !included.empty() ? "Figure 1 is included from '" + included + "', a file the harness does not read (no figure's data is in the source)"
                                       : "Figure 1 is absent from the source (" + std::string(found ? "\\includegraphics{ } names no file" : "no \\includegraphics") + ")") +
           ": the caption's statements are about a figure the text does not carry. For context only, not as proof: at N = 15 "
           "the errors above, read by the harness's own thresholds (1/10 and 1/500 of the amplitude), " +
           (both_satisfactory && named_close ? "agree with the caption" : "do not agree with the caption") + "; table1 redraws the figure (figure1.svg).";
  return judged;
}

}  // namespace

void add_figure1_check(check_registry& checks) { checks.add("figure1", check_figure1); }

}  // namespace simpson::verify::detail
