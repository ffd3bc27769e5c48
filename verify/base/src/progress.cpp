#include <simpson/verify/progress.hpp>

#include <simpson/verify/interruption.hpp>

namespace simpson::verify {

void progress_step(const progress_sink& sink, const std::string& section, const std::string& what, double fraction) {
  throw_if_interrupted();  // every unit of work a section reports is also a point where it stops
  if (sink) sink(section, what, fraction);
}

}  // namespace simpson::verify
