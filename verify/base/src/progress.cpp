#include <simpson/verify/progress.hpp>

#include <simpson/verify/interruption.hpp>

#include <utility>

namespace simpson::verify {
namespace {

progress_sink& current_sink() {
  static progress_sink sink;
  return sink;
}

}  // namespace

progress_sink set_progress_sink(progress_sink sink) { return std::exchange(current_sink(), std::move(sink)); }

void progress_step(const std::string& section, const std::string& what, double fraction) {
  throw_if_interrupted();  // every unit of work a section reports is also a point where it stops
  if (const progress_sink& sink = current_sink()) sink(section, what, fraction);
}

}  // namespace simpson::verify
