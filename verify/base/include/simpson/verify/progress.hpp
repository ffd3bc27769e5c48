#pragma once
// Progress of long sections on stderr: a section calls progress_step() after each unit of work
// (a work_precision configuration, a long_time window) with the sink its settings carry; the CLI's
// run gives each section its sink, which decides how often to print (a few lines a second at most).
// Without a sink nothing is printed.

#include <functional>
#include <string>

namespace simpson::verify {

/// (section, what was just done, fraction of the section done in [0, 1], or negative when unknown)
using progress_sink = std::function<void(const std::string&, const std::string&, double)>;

/// Reports one unit of work done to `sink` (empty: to no one); throws simpson::verify::interrupted
/// when the run was asked to stop (interruption.hpp), so every section that reports progress stops
/// between two of its units.
void progress_step(const progress_sink& sink, const std::string& section, const std::string& what, double fraction = -1);

}  // namespace simpson::verify
