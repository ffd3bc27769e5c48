#pragma once
// One checkable statement of the paper, how it is checked, and what the check found.

#include <simpson/precision.hpp>

#include <simpson/verify/json.hpp>
#include <simpson/verify/verdict.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace simpson::verify {

/// What a check is given: the precisions of the numeric rechecks, the seed and how many random
/// samples each recheck draws per precision.
struct paper_reading;
class run_memo;             // run_memo.hpp: what a run computes once
struct corrected_formula;  // formula_reference.hpp: a printed formula's proved correction

/// Corrections of printed formulas a claim is judged again with (its consequences traced): each put
/// in where the claim reads its formula (the result's `printed` says `corrected: true` when one was).
struct formula_corrections {
  std::vector<std::shared_ptr<const corrected_formula>> corrected;
};

struct claim_book;  // ledger.hpp

struct run_context {
  std::vector<precision> precisions;
  std::uint64_t seed = 0;
  unsigned samples = 0;
  /// The formulas read from the paper's source; without it, formula claims check our
  /// transcription only.
  const paper_reading* paper = nullptr;
  /// Where a prose claim's check records the sentences it quotes (quoted_words.hpp); null when the
  /// check is run on its own.
  json* quotes = nullptr;
  /// Decimal digits of the first interval evaluation of a numeric claim, and the most digits it
  /// may rise to (doubling) before the claim is undecided.
  unsigned enclosure_digits = 40;
  unsigned enclosure_budget_digits = 640;
  /// Corrected formulas to read instead of the printed ones (a consequence's second judgment); null
  /// for a judgment of the document as printed.
  const formula_corrections* corrections = nullptr;
  /// The book the claim belongs to (ledger.hpp): the claims its run may judge again (the paper's
  /// earlier text) and the declarations its document is read with; null for a check run on its own.
  const claim_book* book = nullptr;
  /// What the run computes once for several of its claims and sections (run_memo.hpp); null for a
  /// check run on its own, which then computes everything itself.
  run_memo* memo = nullptr;
};

/// A finding in one line, "printed X, should be Y": what the paper prints and what should stand
/// there, in the paper's notation (TeX when `tex`, else words), and where (an entry, a term, a
/// sentence's words); the derivation behind it stays in the correction and the evidence.
struct amendment {
  std::string where;
  std::string printed;
  std::string should_be;
  bool tex = true;
  bool operator==(const amendment& o) const { return where == o.where && printed == o.printed && should_be == o.should_be && tex == o.tex; }
};

/// The class of a finding or of a remark, one policy for all (docs/findings.md, "How findings are
/// classified"). A finding is false under every reasonable reading; a claim true under the reading an
/// expert referee gives it holds, with a remark of its class at most:
///   erratum         a formula or statement false as printed; its correction proved;
///   wording         (a remark) the words say more, or less, than the mathematics that holds, and an
///                   expert reads them as meant; or (a finding) false under every reading;
///   derivation_gap  (a remark) the conclusion holds, but the printed argument does not reach it;
///   naming          (a remark) a result left unnamed or attributed to the wrong principle or person;
///   unverifiable    material the claim needs is absent from the source (a figure, a reference);
///   prose           slips of spelling in the prose, counted apart from the findings about the mathematics.
enum class finding { none, erratum, wording, derivation_gap, naming, unverifiable, prose };

inline std::string to_string(finding f) {
  switch (f) {
    case finding::none: return "none";
    case finding::erratum: return "erratum";
    case finding::wording: return "wording";
    case finding::derivation_gap: return "derivation gap";
    case finding::naming: return "naming";
    case finding::unverifiable: return "unverifiable";
    case finding::prose: return "prose";
  }
  return "?";
}

/// What a check found. `evidence` has one member per method ("exact", "numeric", ...).
struct claim_result {
  verdict outcome = verdict::fails;
  json evidence = json::object();
  std::string correction;  // the corrected statement, for errata
  std::string note;        // conditions not stated in the paper, sufficiency, caveats
  /// For a finding (erratum, wording, naming): "printed X, should be Y", one per place.
  std::vector<amendment> amendments;
  /// For a claim whose formula is read from the paper: where ({label, line, tex, parsed}) and
  /// what GiNaC proved of it; null for a claim typed from prose.
  json printed;
  /// For a claim typed from the prose: the sentences it judges, as quoted from the paper
  /// ({source, line, text, pattern, words, parsed}); empty for a claim that quotes none.
  json quoted = json::array();
  /// For a claim that reads the document's text as a whole (its prose's spelling, its citations)
  /// rather than one formula or one sentence.
  bool reads_whole_text = false;
  /// Seconds the GiNaC proof of the printed formula took (reported under "timing", never in evidence).
  double printed_seconds = 0;
  /// The Coq certificate (certificates/<id>.v), printed from the identities GiNaC proved; empty when
  /// none is exported, `certificate_missing` then saying why.
  std::string certificate;
  std::vector<std::string> certificate_lemmas;
  std::string certificate_missing;
  /// The negation of each identity GiNaC refuted (an erratum's printed statement, a wrong formula of
  /// an altered paper), shown at a counterexample point (certificates/<id>_refuted.v); may be present
  /// without `certificate`.
  std::string refutation;
  std::vector<std::string> refutation_lemmas;
  /// The printed formulas this erratum's correction replaces, with what should stand there: the
  /// claims that read them are judged again with them (ledger.hpp, trace_consequences).
  std::vector<std::shared_ptr<const corrected_formula>> corrected_formulas;
  /// For a claim that holds under the reading an expert gives its words, but whose words say more or
  /// less than what holds: a remark, of its class (wording, naming, derivation gap), shown beside the
  /// verdict and never counted among the findings; its "printed X, should be Y" in `amendments`.
  /// decide() keeps it only on a claim that holds. Empty: no remark.
  std::string remark;
  finding remark_kind = finding::none;
  /// An erratum whose printed formula is a nonzero constant multiple of the one derived: its zeros,
  /// what the text uses it for, are the same (a slip counted apart from substantive errors).
  /// decide() keeps it only on an erratum.
  bool constant_factor = false;
};

/// The class spelled `text` (to_string's spelling), or none.
inline std::optional<finding> finding_of_name(const std::string& text) {
  for (const finding f : {finding::none, finding::erratum, finding::wording, finding::derivation_gap, finding::naming, finding::unverifiable, finding::prose}) {
    if (to_string(f) == text) return f;
  }
  return std::nullopt;
}

/// Whether a class may be a remark's, on a claim that holds: wording, derivation gap, naming.
inline bool remark_class(finding f) { return f == finding::wording || f == finding::derivation_gap || f == finding::naming; }

/// Whose statement a claim is: the paper's, or the harness's own (a lemma the proofs use, a
/// finding beyond the paper), counted apart.
/// Where a claim comes from: the paper (or the document a claims file checks), beyond it (a claim of
/// the harness about the scheme that the paper does not make), or the harness's own statement about
/// itself (a lemma, a finding of the experiments). Only the paper's are findings about the paper.
enum class claim_origin { paper, beyond, harness };

inline std::string to_string(claim_origin o) { return o == claim_origin::paper ? "paper" : o == claim_origin::beyond ? "beyond" : "harness"; }

/// What decides a claim, from its record: a proof shape of the engine (`shape`), a fact an experiment
/// publishes (`observes`: published_fact.hpp), or a check the book registers by name (`check`).
/// Typed, so that no code reads a claim's kind back out of a string.
struct shape_decider {
  std::string shape;
  bool operator==(const shape_decider& o) const { return shape == o.shape; }
};
struct observation_decider {
  std::string fact;  // "section.name"
  bool operator==(const observation_decider& o) const { return fact == o.fact; }
};
struct check_decider {
  std::string check;
  bool operator==(const check_decider& o) const { return check == o.check; }
};
using decider = std::variant<shape_decider, check_decider, observation_decider>;

/// The decider as the claims listing spells it: "shape <name>", "observes <fact>", or the check's name.
inline std::string to_string(const decider& d) {
  if (const shape_decider* s = std::get_if<shape_decider>(&d)) return "shape " + s->shape;
  if (const observation_decider* o = std::get_if<observation_decider>(&d)) return "observes " + o->fact;
  return std::get<check_decider>(d).check;
}

struct claim {
  std::string id;         // stable kebab-case
  std::string section;    // section of the paper
  std::string equation;   // the paper's equation label, or "prose"
  std::string statement;  // as printed
  std::vector<std::string> methods;
  verdict expected;
  std::function<claim_result(const run_context&)> check;
  /// The class of the finding when the expected verdict is not `holds`; and, for a finding that is
  /// a consequence of another (it inherits a typo), the id of its cause: the summary counts it once.
  finding kind = finding::none;
  std::string follows_from = {};
  bool typographical = false;  // a slip of the pen (a wrong index, a letter for another), not of the mathematics
  claim_origin origin = claim_origin::paper;
  /// From the claim's record (claims_file.hpp): what decides it, whether it is a headline claim (the
  /// report's speed line), and why no Coq statement is exported when none is.
  decider decided_by = check_decider{};
  /// For a claim a proof shape decides: the labels of the displays it reads (provenance finds the
  /// claims that read a display through them).
  std::vector<std::string> labels_read = {};
  bool headline = false;
  std::string coq_none = {};
  /// For an expected erratum: the proved correction its record recorded (`correction`), the
  /// erratum's content; for an expected remark (`expected` holds, a class in `kind`), the remark's
  /// text as recorded (`remark`). The same verdict with another correction or remark (a second error
  /// in a formula already known to be wrong) is a changed verdict. Empty: not recorded.
  std::string expected_correction = {};
  /// The digest of the text the claim read when its record was written (`reads`: the displays and
  /// sentences it reads, reads_digest()): a claim recorded as a finding or a remark that now holds
  /// without it is a fix only when that text changed. Empty: not recorded.
  std::string expected_reads = {};
  /// For an erratum: the claims that draw the text's conclusions from what it is about (its record's
  /// conclusions_kept). When each holds in the run, the erratum is an inconsistency that changes no
  /// conclusion, counted apart from substantive errors; when one is not run or does not hold, it is not.
  std::vector<std::string> conclusions_kept = {};
  /// Whether the record expects a remark: it holds, with a remark of class `kind`.
  bool expects_remark() const { return expected == verdict::holds && kind != finding::none; }
};

}  // namespace simpson::verify
