#pragma once
// The canonical text's math as a reader writes it, for words a report shows (a finding's one line,
// a plot's tic): Greek names as letters, powers as superscripts, sqrt(2) as √2, a product by
// juxtaposition ("h^2*omega^2-8" as "h²ω²-8", "2 sqrt(2)" as "2√2"). Spans between $…$ are TeX and
// are left as they are; a word that only starts with a Greek name ("betas") is left too.

#include <string>

namespace simpson::verify {

std::string readable_math(const std::string& text);

}  // namespace simpson::verify
