// Gappa and coqc on a round-off problem (gappa_run.hpp).

#include <simpson/verify/gappa_run.hpp>

#include <simpson/verify/command.hpp>
#include <simpson/verify/coq_batch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <unistd.h>

namespace simpson::verify {

rational parse_gappa_number(const std::string& text) {
  using boost::multiprecision::cpp_int;
  std::size_t at = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (negative) ++at;
  const std::size_t digits_end = text.find_first_not_of("0123456789", at);
  const std::string digits = text.substr(at, digits_end == std::string::npos ? std::string::npos : digits_end - at);
  if (digits.empty()) throw std::invalid_argument("not a number Gappa prints: '" + text + "'");
  rational value{cpp_int(digits)};
  if (digits_end != std::string::npos) {
    if (text[digits_end] != 'b') throw std::invalid_argument("not a number Gappa prints: '" + text + "'");
    const long exponent = std::stol(text.substr(digits_end + 1));
    const rational power{cpp_int(1) << static_cast<unsigned>(exponent < 0 ? -exponent : exponent)};
    value = exponent < 0 ? rational(value / power) : rational(value * power);
  }
  return negative ? -value : value;
}

namespace {

/// Gappa's Coq output states each rewriting hint as a section Hypothesis ("Hypothesis a3 : r26 =
/// r45."), which its final lemma then assumes. Each becomes a Lemma proved in the file: by ring
/// (the telescoping hints), or, for the hints that state Φ̂ − Φ with the stored and exact
/// coefficients, with the binary constants unfolded to rationals and field. coqc then checks the
/// hints too, and the bound assumes nothing but the section's input variables.
std::string with_hints_proved(const std::string& certificate) {
  static const std::regex hypothesis(R"(Hypothesis (a[0-9]+) : ([^\n]*)\.\n)");
  std::string out = std::regex_replace(
      certificate, hypothesis, "Lemma $1 : $2.\nProof. first [ring | unfold float2R, Float1, Defs.F2R; simpl; unfold Z.pow_pos; simpl; field]. Qed.\n");
  // ring and field on R need the reals' field structure (RealField: few names, none Gappa's proofs use).
  const std::string library = "Require Import Gappa.Gappa_library.\n";
  if (const std::size_t at = out.find(library); at != std::string::npos) out.insert(at + library.size(), "Require Import Coq.setoid_ring.RealField.\n");
  return out;
}

void write_file(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

std::string read_file(const std::filesystem::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

/// The enclosures Gappa printed under "Results:", by expression ("p1 - p_exact": {lo, hi}).
std::map<std::string, std::pair<rational, rational>> gappa_results(const std::string& output) {
  std::map<std::string, std::pair<rational, rational>> out;
  std::istringstream in(output);
  std::string line;
  bool results = false;
  while (std::getline(in, line)) {
    if (line.rfind("Results", 0) == 0) {
      results = true;
      continue;
    }
    if (!results) continue;
    const std::size_t in_at = line.find(" in ");
    if (in_at == std::string::npos) continue;
    const std::string name = line.substr(line.find_first_not_of(' '), in_at - line.find_first_not_of(' '));
    std::string rest = line.substr(in_at + 4);
    // Drop Gappa's decimal comments in braces.
    for (std::size_t open = rest.find('{'); open != std::string::npos; open = rest.find('{')) {
      rest.erase(open, rest.find('}', open) - open + 1);
    }
    std::string cleaned;
    for (const char c : rest) {
      if (c != ' ' && c != '[' && c != ']') cleaned += c;
    }
    const std::size_t comma = cleaned.find(',');
    const rational lo = parse_gappa_number(cleaned.substr(0, comma));
    const rational hi = comma == std::string::npos ? lo : parse_gappa_number(cleaned.substr(comma + 1));
    out[name] = {lo, hi};
  }
  return out;
}

rational larger_end(const std::pair<rational, rational>& e) { return abs(e.first) > abs(e.second) ? abs(e.first) : abs(e.second); }

}  // namespace

roundoff_proof prove_roundoff(const roundoff_problem& problem, bool check_with_coqc) {
  roundoff_proof out;
  if (!program_on_path("gappa")) {
    out.reason = "gappa not found (scripts/install-deps installs Debian's gappa): nothing proved";
    return out;
  }
  const scratch_directory work("simpson-gappa");
  // 1. The enclosures.
  write_file(work.path() / "ask.g", gappa_script(problem));
  const command_result asked = run_command("gappa '" + (work.path() / "ask.g").string() + "'");
  std::map<std::string, std::pair<rational, rational>> found;
  try {
    found = gappa_results(asked.output);
  } catch (const std::invalid_argument& e) {
    out.status = proof_status::unproved;
    out.reason = std::string("Gappa's output did not parse: ") + e.what();
    return out;
  }
  const std::string p_error = problem.program.p_result + " - p_exact", q_error = problem.program.q_result + " - q_exact";
  if (asked.output.find("not trivially equal") != std::string::npos) {
    out.status = proof_status::unproved;
    out.reason = "a rewriting hint is not an identity Gappa can check: " + first_lines(asked.output, 6);
    return out;
  }
  if (asked.status != 0 || found.count(p_error) == 0 || found.count(q_error) == 0) {
    out.status = proof_status::unproved;
    out.reason = "Gappa proved no bound: " + first_lines(asked.output, 6);
    return out;
  }
  // 2. No intermediate may overflow.
  const rational largest = parse_gappa_number(largest_finite_text(problem.format));
  for (const rounded_instruction& i : problem.program.body) {
    if (i.op == rounded_op::neg) continue;  // exact: no larger than its operand, itself checked
    const auto it = found.find(i.target);
    if (it == found.end()) {
      out.status = proof_status::unproved;
      out.reason = "Gappa bounded no range for " + i.target + ": overflow cannot be excluded";
      return out;
    }
    if (larger_end(it->second) > largest) {
      out.status = proof_status::unproved;
      out.reason = "overflow possible: " + i.target + " may exceed the largest finite " + problem.format.name + " (|" + i.target +
                   "| up to " + larger_end(it->second).str() + ")";
      return out;
    }
  }
  // 3. The bounds found, stated and proved again, exported to Coq.
  out.bounds = {larger_end(found.at(p_error)), larger_end(found.at(q_error))};
  out.script = gappa_script(problem, out.bounds);
  write_file(work.path() / "claim.g", out.script);
  const command_result exported = run_command("gappa -Bcoq '" + (work.path() / "claim.g").string() + "' > '" +
                                              (work.path() / "claim_gappa.v").string() + "'");
  if (exported.status != 0) {
    out.status = proof_status::unproved;
    out.reason = "Gappa did not prove its own bound again: " + first_lines(exported.output, 6);
    return out;
  }
  out.certificate = with_hints_proved(read_file(work.path() / "claim_gappa.v"));
  out.status = proof_status::proved;
  // 4. coqc on the certificate.
  if (!check_with_coqc) {
    out.coq = "not checked";
    return out;
  }
  out.coq = coqc_check(out.certificate, "claim_gappa");
  if (out.coq == "checked") {
    const command_result version = run_command("coqc --print-version");
    out.coq_version = version.output.substr(0, version.output.find(' '));
  }
  return out;
}

std::string coqc_check(const std::string& text, const std::string& module) {
  if (!program_on_path("coqc")) return "not checked: coqc not found (scripts/install-deps installs Debian's coq and libcoq-gappa)";
  const coq_verdict v = check_with_coqc({{module, text}}, 1).front();
  return v.accepted ? "checked" : "rejected: " + v.message;
}

}  // namespace simpson::verify
