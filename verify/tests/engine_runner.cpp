// engine-runner: a document checked with its claims file by the claims engine alone (verify/prove,
// verify/shapes): no core, no ledger, no experiments on its link line (engine.fence checks that).
// It reads the claims file with no deciders of its own (book_deciders{}), binds it to the document,
// runs every claim (decide.hpp) and traces the consequences, and writes the verdicts as report.json
// ({"claims": [{id, verdict, remark, note, follows_from}], "provenance": {...}}: the fields the notes'
// and the shapes' tests read, and report.json's provenance of the text checked). It shows that the
// engine is a library a note's check needs nothing else of.
//
//   engine-runner --paper NOTE.tex --claims-file CLAIMS.toml --out DIR [--no-certify] [--quiet]
//
// Exit 0: every claim judged; 2: bad input (one line); 3: a harness fault. It certifies nothing
// (--no-certify is accepted, as simpson-verify's note runs pass it).

#include <simpson/verify/claims_file.hpp>
#include <simpson/verify/claim_book.hpp>
#include <simpson/verify/consequences.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/provenance.hpp>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

using namespace simpson::verify;

namespace {

std::string file_text(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument("claims file '" + path + "': cannot be read");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

/// The claims' verdicts, and the provenance of the text they read (its earlier displays judged again).
nlohmann::json verdicts(const std::string& paper, const std::string& claims_file) {
  claim_book book = read_claim_book(file_text(claims_file), claims_file, book_deciders{});
  const claims_document* document = book.checked_document();
  if (document == nullptr) throw std::invalid_argument("claims file '" + claims_file + "': no [document]; the engine alone checks a document's claims");
  const paper_reading reading = read_note(load_document(paper, document->title));
  check_claims_file_formulas(book, reading.source);
  run_context ctx;
  ctx.paper = &reading;
  ctx.book = &book;
  std::vector<claim_result> results;
  for (const claim& c : book.claims) results.push_back(check_claim(c, ctx));
  std::vector<const claim*> claims;
  std::vector<const claim_result*> judged;
  for (std::size_t k = 0; k < book.claims.size(); ++k) {
    claims.push_back(&book.claims[k]);
    judged.push_back(&results[k]);
  }
  const std::vector<std::optional<consequence>> traced = trace_consequences(claims, judged, ctx, check_claim);
  nlohmann::json out = nlohmann::json::array();
  std::vector<checked_claim> checked;
  for (std::size_t k = 0; k < book.claims.size(); ++k) checked.push_back({book.claims[k].id, results[k].quoted, results[k].outcome});
  for (std::size_t k = 0; k < book.claims.size(); ++k) {
    const claim_result& r = results[k];
    nlohmann::json entry = {{"id", book.claims[k].id}, {"verdict", to_string(r.outcome)}, {"note", r.note}};
    if (!r.remark.empty()) entry["remark"] = {{"class", to_string(r.remark_kind)}, {"text", r.remark}};
    if (traced[k]) entry["follows_from"] = traced[k]->cause;
    out.push_back(std::move(entry));
  }
  return {{"claims", out}, {"provenance", provenance_json(reading, ctx, checked)}};
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"The claims engine alone: a document checked with its claims file."};
  std::string paper, claims_file, out;
  bool ignored = false;
  app.add_option("--paper", paper, "the document's LaTeX")->required();
  app.add_option("--claims-file", claims_file, "its claims file")->required();
  app.add_option("--out", out, "where report.json is written")->required();
  app.add_flag("--no-certify,--quiet", ignored, "accepted; the runner certifies nothing and prints only errors");
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "engine-runner: %s\n", e.what());
    return 2;
  }
  nlohmann::json report;
  try {
    report = verdicts(paper, claims_file);
  } catch (const std::invalid_argument& e) {  // bad input, as simpson-verify's (a claims_file_error is one)
    for (const std::string& line : simpson::verify::lines_of(e.what())) std::fprintf(stderr, "engine-runner: %s\n", line.c_str());  // a claims file's refusals, one a line
    return 2;
  } catch (const std::domain_error& e) {
    std::fprintf(stderr, "engine-runner: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "engine-runner: internal error (a bug in the harness): %s\n", e.what());
    return 3;
  }
  std::filesystem::create_directories(out);
  std::ofstream(std::filesystem::path(out) / "report.json") << report.dump(2) << '\n';
  return 0;
}
