// Claims files (claims_file.hpp): the embedded claims/paper.toml is the ledger, record for record;
// a file that does not read is named with its line and field, one fault at a time.

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/ledger.hpp>
#include <simpson/verify/printed_checks.hpp>

#include "check_registry.hpp"

#include <gtest/gtest.h>

#include <set>

namespace simpson::verify {
namespace {

bool known(const std::string& /*field*/, const std::string& name) {
  return name == "a-check" || name == "b-check";
}

const std::string good_record = R"(
[[claim]]
id = "first"
section = "2"
equation = "prose"
statement = 'It holds.'
methods = ["exact"]
check = "a-check"
expected = "holds"
)";

/// The error a claims file gives, or "" when it reads.
std::string error_of(const std::string& text) {
  try {
    read_claims_file(text, "test.toml", known);
  } catch (const claims_file_error& e) {
    return e.what();
  }
  return "";
}

TEST(ClaimsFile, TheEmbeddedFileIsTheLedgerRecordForRecord) {
  const std::vector<claim_record> records = read_claims_with_known_checks(embedded_claims_text(), "claims/paper.toml");
  ASSERT_EQ(records.size(), paper_book().claims.size());
  std::set<std::string> headline;
  for (std::size_t k = 0; k < records.size(); ++k) {
    EXPECT_EQ(records[k].id, paper_book().claims[k].id);
    EXPECT_EQ(decider_of(records[k]), paper_book().claims[k].decided_by);
    EXPECT_EQ(records[k].expected, paper_book().claims[k].expected) << records[k].id;
    if (records[k].headline) headline.insert(records[k].id);
  }
  EXPECT_EQ(headline, (std::set<std::string>{"phi3-det", "discriminant-factorization", "stability-condition", "hd-invariance", "truncation-1440"}));
  EXPECT_EQ(paper_book().find("abstract-explicit").follows_from, "phi3-explicit");
  EXPECT_FALSE(paper_book().find("table-orders").coq_none.empty());
}

TEST(ClaimsFile, ACheckBringsItsFacetsUnderItsOneName) {
  // The record names the check alone; the printed formulas it reads and its Coq goals are the
  // check's, registered with it (check_registry.hpp).
  const detail::registered_check* derivation = detail::registered_checks().find("derivation-phi3");
  ASSERT_NE(derivation, nullptr);
  EXPECT_EQ(derivation->formulas, (std::vector<std::string>{"Phi3"}));
  EXPECT_TRUE(reads_printed_formula(paper_book().find("derivation-phi3")));
  EXPECT_FALSE(derivation->coq_goals);
  // A claim a proof shape decides names no check: it reads the displays its arguments name.
  EXPECT_EQ(detail::registered_checks().find("phi3-det"), nullptr);
  EXPECT_EQ(paper_book().find("phi3-det").decided_by, decider{shape_decider{"determinant"}});
  EXPECT_EQ(to_string(paper_book().find("phi3-det").decided_by), "shape determinant");
  EXPECT_EQ(paper_book().find("hd-invariance").labels_read, (std::vector<std::string>{"Phi3", "hamiltonien-discret"}));
  EXPECT_TRUE(reads_printed_formula(paper_book().find("phi3-det")));
  const detail::registered_check* shears = detail::registered_checks().find("phi3-shear-factorization");
  ASSERT_NE(shears, nullptr);
  EXPECT_TRUE(shears->coq_goals);
  EXPECT_FALSE(reads_printed_formula(paper_book().find("phi3-shear-factorization")));
  // Named under the check, not the claim: figure1-statements's check is figure1.
  EXPECT_EQ(paper_book().find("figure1-statements").decided_by, decider{check_decider{"figure1"}});
  EXPECT_NE(detail::registered_checks().find("figure1"), nullptr);
  // A facet for a check that is not registered is a harness fault.
  detail::check_registry registry;
  EXPECT_THROW(registry.add_coq_goals("nowhere", [] { return std::vector<detail::proof_goal>{}; }), std::logic_error);
  registry.add("somewhere", [](const run_context&) { return detail::decider_evidence{}; });
  registry.add_coq_goals("somewhere", [] { return std::vector<detail::proof_goal>{}; });
  EXPECT_THROW(registry.add_coq_goals("somewhere", [] { return std::vector<detail::proof_goal>{}; }), std::logic_error);
}

TEST(ClaimsFile, AGoodRecordReadsWithItsDefaults) {
  const std::vector<claim_record> records = read_claims_file(good_record, "test.toml", known);
  ASSERT_EQ(records.size(), 1u);
  EXPECT_EQ(records[0].line, 2);
  EXPECT_EQ(records[0].kind, finding::none);
  EXPECT_EQ(records[0].origin, claim_origin::paper);
  EXPECT_FALSE(records[0].headline);
}

struct bad_file {
  std::string name, text, message;  // the message names the file, line and field
};

void PrintTo(const bad_file& f, std::ostream* out) { *out << f.name; }

class BadClaimsFile : public testing::TestWithParam<bad_file> {};

TEST_P(BadClaimsFile, IsNamedWithItsLineAndField) {
  EXPECT_EQ(error_of(GetParam().text), GetParam().message);
}

std::string replaced(std::string text, const std::string& from, const std::string& to) {
  text.replace(text.find(from), from.size(), to);
  return text;
}

INSTANTIATE_TEST_SUITE_P(
    Faults, BadClaimsFile,
    testing::Values(
        bad_file{"syntax", "[[claim]]\nid = \"x\nsection = 1\n", "claims file 'test.toml', line 2: Error while parsing string: unescaped control characters other than TAB (U+0009) are "
                 "explicitly prohibited"},
        bad_file{"unknown_field", replaced(good_record, "expected", "colour = \"red\"\nexpected"),
                 "claims file 'test.toml', line 9, field 'colour': not a field of a claim record (docs/claims-file.md)"},
        bad_file{"missing_field", replaced(good_record, "statement = 'It holds.'\n", ""),
                 "claims file 'test.toml', line 2, field 'statement': missing (every record has it)"},
        bad_file{"wrong_type", replaced(good_record, "methods = [\"exact\"]", "methods = \"exact\""),
                 "claims file 'test.toml', line 7, field 'methods': must be a non-empty array of strings"},
        bad_file{"duplicate_id", good_record + good_record,
                 "claims file 'test.toml', line 12, field 'id': 'first' is already the id of the record at line 2"},
        bad_file{"not_kebab", replaced(good_record, "\"first\"", "\"First_one\""),
                 "claims file 'test.toml', line 3, field 'id': 'First_one' is not kebab-case (a-z, 0-9, -)"},
        bad_file{"unknown_check", replaced(good_record, "a-check", "c-check"),
                 "claims file 'test.toml', line 8, field 'check': no check is named 'c-check'"},
        bad_file{"printed_is_the_checks", replaced(good_record, "expected = \"holds\"", "expected = \"holds\"\nprinted = \"a-check\""),
                 "claims file 'test.toml', line 10, field 'printed': not a field of a claim record (docs/claims-file.md)"},
        bad_file{"bad_verdict", replaced(good_record, "\"holds\"", "\"hold\""),
                 "claims file 'test.toml', line 9, field 'expected': 'hold' is not a verdict (holds, erratum, fails, unverifiable, ...)"},
        bad_file{"finding_missing", replaced(good_record, "\"holds\"", "\"erratum\""),
                 "claims file 'test.toml', line 9, field 'finding': missing: an expected 'erratum' is a finding, and says its class"},
        bad_file{"never_expected", replaced(good_record, "expected = \"holds\"", "expected = \"undecided\""),
                 "claims file 'test.toml', line 9, field 'expected': 'undecided' is never expected: it is no judgment of the document "
                 "(expect holds, erratum, fails or unverifiable)"},
        // A claim that holds may carry a remark of class wording, naming or derivation gap; an erratum is no remark's class.
        bad_file{"finding_for_holds", replaced(good_record, "expected = \"holds\"", "expected = \"holds\"\nfinding = \"erratum\""),
                 "claims file 'test.toml', line 10, field 'finding': 'erratum' is no class of a remark on a claim that holds (wording, naming, derivation gap)"},
        bad_file{"remark_without_class", replaced(good_record, "expected = \"holds\"", "expected = \"holds\"\nremark = 'a remark'"),
                 "claims file 'test.toml', line 10, field 'remark': given for a claim not expected to hold with a remark: a remark's record says "
                 "expected = \"holds\" and its class in `finding`"},
        bad_file{"reads_not_a_digest", replaced(good_record, "expected = \"holds\"", "expected = \"holds\"\nreads = \"xyz\""),
                 "claims file 'test.toml', line 10, field 'reads': 'xyz' is not a digest of what the claim reads (16 hexadecimal digits)"},
        bad_file{"bad_finding", replaced(good_record, "expected = \"holds\"", "expected = \"erratum\"\nfinding = \"typo\""),
                 "claims file 'test.toml', line 10, field 'finding': 'typo' is not a class of finding (erratum, wording, derivation gap, naming, unverifiable, prose)"},
        bad_file{"unknown_cause", replaced(good_record, "expected = \"holds\"", "expected = \"holds\"\nfollows_from = \"zeroth\""),
                 "claims file 'test.toml', line 2, field 'follows_from': no record has the id 'zeroth'"},
        // Found by the fuzzer: a cause reached first through another record's chain was taken for a record.
        bad_file{"unknown_cause_down_a_chain",
                 replaced(good_record, "expected = \"holds\"", "expected = \"holds\"\nfollows_from = \"second\"") +
                     replaced(replaced(good_record, "\"first\"", "\"second\""), "expected = \"holds\"", "expected = \"holds\"\nfollows_from = \"third\""),
                 "claims file 'test.toml', line 12, field 'follows_from': no record has the id 'third'"},
        bad_file{"cycle",
                 replaced(good_record, "expected = \"holds\"", "expected = \"holds\"\nfollows_from = \"second\"") +
                     replaced(replaced(good_record, "\"first\"", "\"second\""), "expected = \"holds\"", "expected = \"holds\"\nfollows_from = \"first\""),
                 "claims file 'test.toml', line 2, field 'follows_from': following the causes from 'first' comes back to 'first' (a cycle)"},
        bad_file{"bad_origin", replaced(good_record, "expected = \"holds\"", "expected = \"holds\"\norigin = \"referee\""),
                 "claims file 'test.toml', line 10, field 'origin': 'referee' is not 'paper', 'beyond' or 'harness'"},
        // A claim beyond the paper that its record leaves the paper's would count as a finding about the paper.
        bad_file{"beyond_as_the_paper", replaced(good_record, "section = \"2\"", "section = \"beyond\""),
                 "claims file 'test.toml', line 4, field 'origin': a claim of the section 'beyond' is not the paper's: say origin = \"beyond\" (or \"harness\")"},
        bad_file{"other_table", "[claims]\nid = 1\n",
                 "claims file 'test.toml', line 1, field 'claims': not a table of a claims file ([document], [symbols], [[claim]])"},
        bad_file{"document_without_symbols", "[document]\ntitle = 'T'\n" + good_record,
                 "claims file 'test.toml', line 1, field 'symbols': missing: a [document] declares its symbols in [symbols]"},
        bad_file{"symbol_thrice", "[document]\ntitle = 'T'\n[symbols]\nreal = ['q']\nfunctions = ['q']\npositive = ['q']\n" + good_record,
                 "claims file 'test.toml', line 4, field 'symbols.real': 'q' is declared twice"},
        bad_file{"document_without_title", "[document]\n[symbols]\npositive = ['h']\n" + good_record,
                 "claims file 'test.toml', line 1, field 'document.title': missing: a phrase the document prints (its title)"},
        bad_file{"symbol_twice", "[document]\ntitle = 'T'\n[symbols]\npositive = ['h']\nreal = ['h']\n" + good_record,
                 "claims file 'test.toml', line 5, field 'symbols.real': 'h' is declared twice"},
        bad_file{"check_and_shape", replaced(good_record, "check = \"a-check\"", "check = \"a-check\"\nshape = \"identity\""),
                 "claims file 'test.toml', line 2, field 'check': a record names one of a shape, an observed fact and a check, not two"},
        bad_file{"check_and_observed_fact", replaced(good_record, "check = \"a-check\"", "check = \"a-check\"\nobserves = \"a-check\""),
                 "claims file 'test.toml', line 2, field 'observes': a record names one of a shape, an observed fact and a check, not two"},
        bad_file{"unknown_fact", replaced(good_record, "check = \"a-check\"", "observes = \"table1.nothing\""),
                 "claims file 'test.toml', line 8, field 'observes': no experiment publishes a fact named 'table1.nothing' (simpson-verify --list-facts)"},
        bad_file{"neither_check_nor_shape", replaced(good_record, "check = \"a-check\"\n", ""),
                 "claims file 'test.toml', line 2, field 'shape': missing: a record names the proof shape, the observed fact or the bespoke check that decides it"},
        bad_file{"with_without_shape", replaced(good_record, "check = \"a-check\"", "check = \"a-check\"\nwith = { lhs = \"x\" }"),
                 "claims file 'test.toml', line 9, field 'with': arguments without a shape"},
        bad_file{"empty", "# nothing\n", "claims file 'test.toml', line 1, field 'claim': no [[claim]] record"}),
    [](const testing::TestParamInfo<bad_file>& info) { return info.param.name; });

}  // namespace
}  // namespace simpson::verify
