// Checking many Coq files with few coqc processes (coq_batch.hpp).

#include <simpson/verify/coq_batch.hpp>

#include <simpson/verify/command.hpp>
#include <simpson/verify/interruption.hpp>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <numeric>
#include <regex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>

namespace simpson::verify {
namespace {

bool is_identifier(const std::string& s) {
  static const std::regex identifier("[A-Za-z_][A-Za-z0-9_']*");
  return std::regex_match(s, identifier);
}

/// coqc on one file of a directory: its verdict, coqc's first lines when it rejects.
coq_verdict coqc_file(const std::filesystem::path& directory, const std::string& module, const std::string& text) {
  std::ofstream(directory / (module + ".v")) << text;
  const command_result done = run_command("cd '" + directory.string() + "' && coqc -q '" + module + ".v'");
  if (done.status == 0) return {true, ""};
  return {false, first_lines(done.output, 12)};
}

}  // namespace

std::string coq_modules_file(const std::vector<coq_document>& documents) {
  // `Require Import Reals Lra.` and `From Gappa Require Import Gappa_library.`, one per line, as
  // coqc's users and gappa -Bcoq write them.
  static const std::regex require_line(R"(^\s*(From\s+(\S+)\s+)?Require\s+(Import\s+|Export\s+)?([^.]+(\.[A-Za-z_][A-Za-z0-9_]*)*)\.\s*$)");
  std::set<std::string> names;
  std::vector<std::string> requires_in_order;
  std::set<std::string> required;
  std::string modules;
  for (const coq_document& d : documents) {
    if (!is_identifier(d.name)) throw std::invalid_argument("coqc: document name '" + d.name + "' is not a Coq identifier");
    if (!names.insert(d.name).second) throw std::invalid_argument("coqc: two documents are named '" + d.name + "'");
    std::istringstream in(d.text);
    std::string line, body;
    while (std::getline(in, line)) {
      std::smatch m;
      if (std::regex_match(line, m, require_line)) {
        const std::string from = m[1].matched ? "From " + m[2].str() + " " : "";
        const std::string libraries = m[4].str();
        const std::string require = from + "Require " + libraries + ".";
        if (required.insert(require).second) requires_in_order.push_back(require);
        if (m[3].matched) {
          // Import of a library by its short name: the name it was required by.
          std::string keyword = m[3].str();
          keyword.erase(keyword.find_last_not_of(" \t") + 1);
          body += keyword + " " + libraries + ".\n";
        }
        continue;
      }
      body += line + "\n";
    }
    modules += "Module Cert_" + d.name + ".\n" + body + "End Cert_" + d.name + ".\n\n";
  }
  std::string out = "(* " + std::to_string(documents.size()) + " documents checked as modules of one file. *)\n";
  for (const std::string& r : requires_in_order) out += r + "\n";
  return out + "\n" + modules;
}

unsigned coqc_processes() {
  const unsigned threads = std::thread::hardware_concurrency();
  return threads == 0 ? 2 : threads;
}

unsigned coqc_processes_for(std::size_t documents, unsigned jobs) {
  if (documents == 0) return 0;
  return std::max(1u, std::min<unsigned>(jobs, static_cast<unsigned>(documents)));
}

std::vector<coq_verdict> check_with_coqc(const std::vector<coq_document>& documents, unsigned jobs) {
  std::vector<coq_verdict> verdicts(documents.size());
  if (documents.empty()) return verdicts;
  if (!program_on_path("coqc")) throw std::invalid_argument("coqc was not found (scripts/install-deps installs Debian's coq)");
  coq_modules_file(documents);  // the names checked before any process starts
  jobs = coqc_processes_for(documents.size(), jobs);
  // Longest first, each to the process with the least text so far.
  std::vector<std::size_t> order(documents.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return documents[a].text.size() > documents[b].text.size(); });
  std::vector<std::vector<std::size_t>> shares(jobs);
  std::vector<std::size_t> load(jobs, 0);
  for (const std::size_t k : order) {
    const std::size_t j = static_cast<std::size_t>(std::min_element(load.begin(), load.end()) - load.begin());
    shares[j].push_back(k);
    load[j] += documents[k].text.size();
  }
  for (auto& share : shares) std::sort(share.begin(), share.end());  // the documents' own order inside a file
  throw_if_interrupted();
  const scratch_directory work("simpson-coq");
  std::vector<std::future<coq_verdict>> running;
  for (unsigned j = 0; j < jobs; ++j) {
    std::vector<coq_document> mine;
    for (const std::size_t k : shares[j]) mine.push_back(documents[k]);
    const std::filesystem::path directory = work.path() / ("process" + std::to_string(j));
    std::filesystem::create_directories(directory);
    running.push_back(std::async(std::launch::async, [directory, mine = std::move(mine)] {
      return coqc_file(directory, "batch", coq_modules_file(mine));
    }));
  }
  for (unsigned j = 0; j < jobs; ++j) {
    const coq_verdict batch = running[j].get();
    throw_if_interrupted();  // a coqc stopped by the same Ctrl-C is not a rejection
    for (const std::size_t k : shares[j]) verdicts[k] = batch.accepted ? coq_verdict{true, ""} : coq_verdict{};
    if (batch.accepted) continue;
    // Rejected: which of them, and coqc's message on each, one file at a time.
    for (const std::size_t k : shares[j]) {
      throw_if_interrupted();
      const std::filesystem::path directory = work.path() / ("alone" + std::to_string(k));
      std::filesystem::create_directories(directory);
      verdicts[k] = coqc_file(directory, documents[k].name, documents[k].text);
    }
    // A file that coqc accepts alone but not among the others: the batch's own message, on each.
    bool any_named = false;
    for (const std::size_t k : shares[j]) any_named = any_named || !verdicts[k].accepted;
    if (!any_named) {
      for (const std::size_t k : shares[j]) verdicts[k] = {false, "rejected only when checked with the others: " + batch.message};
    }
  }
  return verdicts;
}

}  // namespace simpson::verify
