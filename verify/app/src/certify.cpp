// Coq certificates: evidence and the check by coqc (certify.hpp).

#include <simpson/verify/certify.hpp>

#include <simpson/verify/command.hpp>
#include <simpson/verify/coq_batch.hpp>
#include <simpson/verify/interruption.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace simpson::verify {
std::string coqc_version() {
  const command_result r = run_command("coqc --version");
  if (r.status != 0) return "";
  const std::string marker = "version ";
  const std::size_t at = r.output.find(marker);
  if (at == std::string::npos) return "";
  std::string v = r.output.substr(at + marker.size());
  return v.substr(0, v.find_first_of(" \n"));
}

std::string certificate_file(const std::string& claim_id) {
  // coqc takes a file's name as its module name, an identifier: '-' becomes '_'.
  std::string module = claim_id;
  for (char& c : module) c = c == '-' ? '_' : c;
  return "certificates/" + module + ".v";
}

std::string refutation_file(const std::string& claim_id) {
  const std::string proved = certificate_file(claim_id);
  return proved.substr(0, proved.size() - 2) + "_refuted.v";
}

std::vector<certificate_document> certificate_documents(const claim_outcome& o) {
  std::vector<certificate_document> out;
  const claim_result& r = o.result;
  if (!r.certificate.empty()) out.push_back({certificate_file(o.checked->id), &r.certificate, &r.certificate_lemmas});
  if (!r.refutation.empty()) out.push_back({refutation_file(o.checked->id), &r.refutation, &r.refutation_lemmas});
  return out;
}

std::vector<std::string> record_certificates(run_record& r, bool check) {
  std::vector<std::string> rejected;
  std::string version;
  if (check) {
    version = coqc_version();
    if (version.empty()) throw std::invalid_argument("--certify: coqc was not found (install Debian's coq)");
  }
  // Every claim's files, checked together: one coqc process per core, not one per file.
  std::vector<coq_document> documents;
  std::vector<std::size_t> owner;  // the outcome each document belongs to
  for (std::size_t k = 0; k < r.outcomes.size(); ++k) {
    claim_outcome& o = r.outcomes[k];
    claim_result& result = o.result;
    const std::vector<certificate_document> files = certificate_documents(o);
    if (files.empty()) {
      result.evidence["coq"] = {{"status", "not exported"},
                                {"reason", result.certificate_missing.empty() ? "no identity to state" : result.certificate_missing}};
      continue;
    }
    json coq{{"status", "exported"}};
    if (!result.certificate.empty()) {
      coq["file"] = files.front().file;
      coq["lemmas"] = result.certificate_lemmas;
    } else {
      coq["reason"] = result.certificate_missing;  // why nothing is proved: only refuted
    }
    if (!result.refutation.empty()) coq["refutation"] = {{"file", files.back().file}, {"lemmas", result.refutation_lemmas}};
    result.evidence["coq"] = coq;
    for (const certificate_document& d : files) {
      const std::string name = std::filesystem::path(d.file).stem().string();
      documents.push_back({name, *d.text});
      owner.push_back(k);
    }
  }
  if (!check || documents.empty()) return rejected;
  const auto start = std::chrono::steady_clock::now();
  const std::vector<coq_verdict> verdicts = check_with_coqc(documents);
  r.coq_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  r.coq_documents = documents.size();
  r.coq_processes = coqc_processes_for(documents.size());
  for (std::size_t k = 0; k < r.outcomes.size(); ++k) {
    json& coq = r.outcomes[k].result.evidence["coq"];
    if (coq.value("status", "") != "exported") continue;
    std::string failure;
    for (std::size_t d = 0; d < documents.size(); ++d) {
      if (owner[d] == k && !verdicts[d].accepted && failure.empty()) failure = documents[d].name + ".v: " + verdicts[d].message;
    }
    if (failure.empty()) {
      coq["status"] = "checked";
      coq["coq_version"] = version;
    } else {
      coq["status"] = "failed";
      coq["coqc_output"] = "certificates/" + failure;
      rejected.push_back(r.outcomes[k].checked->id);
    }
  }
  return rejected;
}

}  // namespace simpson::verify
