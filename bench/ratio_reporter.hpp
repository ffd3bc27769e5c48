#pragma once
// A console reporter that also keeps each benchmark's real time per iteration, so that a benchmark
// program can print ratios of two measured in the same run (`ratio <name> <value>`).

#include <benchmark/benchmark.h>

#include <map>
#include <string>
#include <vector>

namespace simpson::bench {

class ratio_reporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override;
  /// Real seconds per iteration of the benchmark named `name` (its last aggregate, or its run).
  double seconds(const std::string& name) const;

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace simpson::bench
