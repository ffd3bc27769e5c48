// simpson-verify with one claim's check made to throw, for the exit code of a harness fault (3):
//   simpson-verify-with-fault --fault-claim CLAIM_ID [simpson-verify's arguments...]
// The fault enters through the run's seam (run.hpp, claim_checker), not through anything the real
// binary reads.

#include "cli_commands.hpp"

#include <simpson/verify/printed_checks.hpp>

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

int main(int argc, char** argv) {
  using namespace simpson::verify;
  std::vector<char*> args{argv[0]};
  std::string faulty;
  for (int k = 1; k < argc; ++k) {
    if (std::string(argv[k]) == "--fault-claim" && k + 1 < argc) {
      faulty = argv[++k];
    } else {
      args.push_back(argv[k]);
    }
  }
  if (faulty.empty()) {
    std::fprintf(stderr, "usage: simpson-verify-with-fault --fault-claim CLAIM_ID [simpson-verify's arguments...]\n");
    return 2;
  }
  args.push_back(nullptr);
  return simpson_verify_main(static_cast<int>(args.size()) - 1, args.data(), [faulty](const claim& c, const run_context& ctx) {
    if (c.id == faulty) throw std::logic_error("a fault made by the test (" + c.id + "'s check throws)");
    return check_claim(c, ctx);
  });
}
