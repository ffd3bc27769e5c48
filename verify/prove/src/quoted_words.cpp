// The words a prose claim judges: see quoted_words.hpp.

#include <simpson/verify/quoted_words.hpp>

#include <simpson/verify/paper_reading.hpp>

#include <stdexcept>

namespace simpson::verify {

const paper_reading& paper_of(const run_context& ctx) {
  // The document is the run's, passed as a value: nothing falls back to an installed one.
  if (ctx.paper == nullptr) throw std::logic_error("a claim reads its document, but the run was given none (run_context::paper is null)");
  return *ctx.paper;
}

quoted_sentence quote(const run_context& ctx, const std::string& pattern) {
  return quote_sentence(paper_of(ctx).source, pattern, ctx.quotes);
}

}  // namespace simpson::verify
