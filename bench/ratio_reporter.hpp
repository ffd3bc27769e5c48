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
  ratio_reporter() : benchmark::ConsoleReporter(OO_Tabular) {}  // no colour codes in logs
  void ReportRuns(const std::vector<Run>& runs) override;
  /// CPU seconds per iteration of the benchmark named `name` (its median aggregate, or its run):
  /// CPU time, so that another process on the machine disturbs a ratio less.
  double seconds(const std::string& name) const;

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace simpson::bench
