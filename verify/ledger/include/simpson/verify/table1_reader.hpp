#pragma once
// Table 1 and the solution the text states for it, read from the paper: each row quoted as a
// sentence (quoted_sentence.hpp), so a row that is gone or a cell that does not parse throws
// text_changed; the stated solution's q and p read as TeX and checked in GiNaC.

#include <simpson/verify/json.hpp>
#include <simpson/verify/paper_source.hpp>
#include <simpson/verify/printed_table1.hpp>

namespace simpson::verify {

/// The table of `paper`, each row recorded in `quotes` when given. Throws text_changed when a row is
/// gone or its cells do not parse.
printed_table1 read_table1(const paper_source& paper, json* quotes = nullptr);

/// The stated solution's sentence the pattern of read_stated_solution finds.
inline constexpr const char* stated_solution_pattern =
    "We have chosen $ \\, q(t) = {q_exact} $ and $ \\, p(t) = {p_exact} $, with a period $ \\, T = {period} $.";

/// The solution `paper` states (recorded in `quotes` when given). Throws text_changed when the
/// sentence is gone, or when q or p does not read, or q's amplitude and phase are not numbers.
stated_solution read_stated_solution(const paper_source& paper, json* quotes = nullptr);

}  // namespace simpson::verify
