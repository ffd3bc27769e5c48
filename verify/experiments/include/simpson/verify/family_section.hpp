#pragma once
// The family section (issue 30): every Galerkin variational integrator of degree s = 1 … max_degree
// with each quadrature rule (Newton–Cotes, Lobatto and Gauss, up to s + 2 points), derived for the
// harmonic oscillator in our exact kernel (verify/family) and analysed: det Φ, the conserved form,
// the stability bands, the order and its error constant, the known scheme it equals.

#include <simpson/verify/experiment_section.hpp>

#include <memory>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/result_model.hpp>

#include <vector>

namespace simpson::verify {

struct family_settings {
  /// Where the section reports each unit of work done (progress.hpp); none: nowhere.
  progress_sink progress;
  int max_degree = 2;          // s = 1 … max_degree
  double budget_seconds = 60;  // no member is started past this; the rest are listed as not run
  bool ginac = true;           // each member derived again in GiNaC, m, ω, h symbolic
  int node_check_degree = 3;   // up to this s, also with the internal nodes as symbols
  std::vector<long long> pendulum_steps{4, 8, 16, 32, 64};  // steps to t = 5, each twice the one before
};

section_result run_family(const family_settings& s);

/// The family section as a registry entry (experiment_section.hpp).
std::unique_ptr<experiment_section> make_family_section();

}  // namespace simpson::verify
