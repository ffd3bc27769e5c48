#include "ratio_reporter.hpp"

#include <stdexcept>

namespace simpson::bench {

void ratio_reporter::ReportRuns(const std::vector<Run>& runs) {
  ConsoleReporter::ReportRuns(runs);
  for (const Run& run : runs) {
    // With repetitions, keep the median; without, the single run.
    if (run.run_type == Run::RT_Aggregate && run.aggregate_name != "median") continue;
    if (run.iterations == 0) continue;
    seconds_[run.run_name.function_name + (run.run_name.args.empty() ? "" : "/" + run.run_name.args)] =
        run.cpu_accumulated_time / static_cast<double>(run.iterations);
  }
}

double ratio_reporter::seconds(const std::string& name) const {
  const auto it = seconds_.find(name);
  if (it == seconds_.end()) throw std::out_of_range("no benchmark named " + name + " was run");
  return it->second;
}

}  // namespace simpson::bench
