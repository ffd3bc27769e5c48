// Coq certificates: evidence and the check by coqc (certify.hpp).

#include <simpson/verify/certify.hpp>

#include <simpson/verify/command.hpp>
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
  std::filesystem::path work;
  if (check) {
    version = coqc_version();
    if (version.empty()) throw std::invalid_argument("--certify: coqc was not found (install Debian's coq)");
    char pattern[] = "/tmp/simpson-certify-XXXXXX";
    if (::mkdtemp(pattern) == nullptr) throw std::runtime_error("--certify: cannot create a temporary directory");
    work = pattern;
  }
  for (claim_outcome& o : r.outcomes) {
    claim_result& result = o.result;
    const std::vector<certificate_document> documents = certificate_documents(o);
    if (documents.empty()) {
      result.evidence["coq"] = {{"status", "not exported"},
                                {"reason", result.certificate_missing.empty() ? "no identity to state" : result.certificate_missing}};
      continue;
    }
    json coq{{"status", "exported"}};
    if (!result.certificate.empty()) {
      coq["file"] = documents.front().file;
      coq["lemmas"] = result.certificate_lemmas;
    } else {
      coq["reason"] = result.certificate_missing;  // why nothing is proved: only refuted
    }
    if (!result.refutation.empty()) coq["refutation"] = {{"file", documents.back().file}, {"lemmas", result.refutation_lemmas}};
    if (check) {
      double seconds = 0;
      std::string failure;
      for (const certificate_document& d : documents) {
        throw_if_interrupted();
        const std::filesystem::path file = work / std::filesystem::path(d.file).filename();
        std::ofstream(file) << *d.text;
        const auto start = std::chrono::steady_clock::now();
        const command_result done = run_command("cd '" + work.string() + "' && coqc -q '" + file.filename().string() + "'");
        seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        if (done.status != 0 && failure.empty()) failure = d.file + ": " + first_lines(done.output, 12);
      }
      if (failure.empty()) {
        coq["status"] = "checked";
        coq["coq_version"] = version;
        o.coq_seconds = seconds;
      } else {
        coq["status"] = "failed";
        coq["coqc_output"] = failure;
        rejected.push_back(o.checked->id);
      }
    }
    result.evidence["coq"] = coq;
  }
  if (check) {
    std::error_code ignored;
    std::filesystem::remove_all(work, ignored);
  }
  return rejected;
}

}  // namespace simpson::verify
