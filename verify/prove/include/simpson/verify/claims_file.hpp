#pragma once
// A claims file: one TOML record per claim (docs/claims-file.md). The paper's are claims/paper.toml,
// embedded in simpson-verify as the paper is; `--claims-file` reads another.

#include <simpson/verify/claim.hpp>

#include <functional>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace simpson::verify {

/// One argument of a proof shape as a record gives it (`with = { matrix = "Phi" }`): a string, or
/// a list of strings, and the line it is on.
struct shape_argument {
  std::vector<std::string> values;
  bool list = false;
  int line = 0;
};

/// A record's `core`: one of our core's formulas (core_formulas(): "simpson_map", "discrete_energy", ...)
/// bound to the printed formula it implements. The core's template is instantiated in GiNaC with
/// the document's symbols: its parameters m, ω, h (`parameters`, as written: m, \omega, h unless
/// given), its variables in the core's order (`variables`: p and q of a phase point, q_l and q_r of an
/// interval, ...) and the potential (`potential`, for the formulas that take one: V unless given).
/// The record's verdict then also says whether our code computes what is printed.
struct core_binding {
  std::string function;                 // core_formulas()'s name
  std::string formula;                  // a formula reference (formula_reference.hpp)
  std::vector<std::string> variables;   // TeX, in the core's order
  std::vector<std::string> parameters;  // TeX of m, omega, h
  std::string potential;                // the declared function the core's V is
  int line = 0;
};

/// One record, as read.
struct claim_record {
  std::string id;         // kebab-case, unique in the file
  std::string section;    // the paper's section ("6"), "abstract", "beyond", "harness"
  std::string equation;   // the \label of the display the claim reads, or "prose"
  std::string statement;  // what the paper says, for the reports
  std::vector<std::string> methods;
  std::string check;      // the name of the bespoke check that decides it, or
  std::string shape;      // the name of the proof shape that decides it (proof_shapes.hpp), with
  std::map<std::string, shape_argument> with;  // its arguments, or
  std::string observes;   // the fact an experiment publishes that decides it ("table1.printed-orders")
  verdict expected = verdict::holds;
  bool expected_given = false;  // the record says `expected`: a regression guard, not a validation
  finding kind = finding::none;
  std::string follows_from;
  bool typographical = false;
  /// An erratum's conclusions_kept: the claims that draw the text's conclusions from what it is
  /// about; when each of them holds in the run, the erratum changes none of them (run.cpp, claim_outcome::conclusions_standing).
  std::vector<std::string> conclusions_kept;
  claim_origin origin = claim_origin::paper;
  bool headline = false;  // one of the claims whose GiNaC time the report's speed line sums
  std::string coq_none;   // why no Coq statement is exported, when none is
  std::vector<core_binding> core;  // the core's formulas bound to the print (one table or a list of them)
  std::string correction;          // an expected erratum's proved correction, as recorded: its content
  std::string remark;              // an expected remark's text, as recorded (expected holds, `finding` its class)
  std::string reads;               // the digest of the text it read when recorded (reads_digest): a fix changes it
  int line = 0;           // the line of its [[claim]] header
  std::string file;       // the claims file it was read from (what a refusal at run time names)
};

/// What decides a record (its `shape`, `observes` or `check`), typed.
inline decider decider_of(const claim_record& r) {
  if (!r.shape.empty()) return shape_decider{r.shape};
  if (!r.observes.empty()) return observation_decider{r.observes};
  return check_decider{r.check};
}

/// A claims file that does not read: "claims file 'NAME', line N, field 'F': why". Bad input
/// (exit 2 for a file given on the command line).
/// The lines of a refusal's message: a claims file refused in one pass gives one line per refusal,
/// each printed after the program's name.
inline std::vector<std::string> lines_of(const std::string& message) {
  std::vector<std::string> out;
  std::size_t start = 0;
  for (std::size_t end; (end = message.find('\n', start)) != std::string::npos; start = end + 1) out.push_back(message.substr(start, end - start));
  out.push_back(message.substr(start));
  return out;
}

class claims_file_error : public std::invalid_argument {
 public:
  claims_file_error(const std::string& file, int line, const std::string& field, const std::string& why);
  const std::string& file() const noexcept { return file_; }
  int line() const noexcept { return line_; }
  const std::string& field() const noexcept { return field_; }

 private:
  std::string file_;
  int line_;
  std::string field_;
};

/// A claims file's [document]: the file checks a document other than the paper, which prints this
/// phrase (its title: the --paper given must contain it).
struct claims_document {
  std::string title;
  int line = 0;
};

/// A claims file's [symbols], as written (TeX): what decides what the document's TeX leaves open
/// (tex_math.hpp). A name may be a function and a symbol (a state: q(t), dq/dt), nothing else twice.
struct claims_symbols {
  std::vector<std::string> positive;   // symbols > 0 (parameters: m, omega, h)
  std::vector<std::string> real;       // other real symbols (the state: q_0, p_0, ...)
  std::vector<std::string> functions;  // applied as f(x): V, L_d, \psi
  std::vector<std::string> solutions;  // functions that name the exact solution: q(t_n) is its value at the node t_n
  int line = 0;
};

struct claims_file_contents {
  std::optional<claims_document> document;  // none for the paper's own claims
  std::optional<claims_symbols> symbols;    // [symbols]: required with a [document]
  std::vector<claim_record> records;
};

/// Reads and validates the records of `text` (named `file` in errors): TOML syntax, every field
/// known and of its type, the required ones present (`expected` may be left out: holds), ids unique, verdicts, classes and origins
/// spelled as the reports spell them, `finding` given exactly when the expected verdict is a
/// finding, `follows_from` naming another record with no cycle, exactly one of `check`, `shape` and
/// `observes`, and names that `known(field, name)` accepts. Throws
/// claims_file_error at the first fault.
using known_name = std::function<bool(const std::string& field, const std::string& name)>;
claims_file_contents read_claims_contents(const std::string& text, const std::string& file, const known_name& known);

/// The records alone (read_claims_contents).
std::vector<claim_record> read_claims_file(const std::string& text, const std::string& file, const known_name& known);

}  // namespace simpson::verify
