#pragma once
// The words a prose claim judges, quoted from the run's paper (quoted_sentence.hpp, in the paper
// layer): the run's paper, or the embedded one, and the claim's record of what it quoted.

#include <simpson/verify/claim.hpp>
#include <simpson/verify/quoted_sentence.hpp>

#include <string>

namespace simpson::verify {

/// The run's document; throws std::logic_error (a harness fault) when the run was given none.
const paper_reading& paper_of(const run_context& ctx);

/// The sentence of the run's document that matches
/// `pattern`; recorded in ctx.quotes. Throws text_changed naming the pattern when it is not there.
quoted_sentence quote(const run_context& ctx, const std::string& pattern);

}  // namespace simpson::verify
