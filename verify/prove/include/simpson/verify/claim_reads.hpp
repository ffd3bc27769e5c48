#pragma once
// What a claim read of its document, as one digest: the displays (each formula reference and its TeX)
// and the sentences (each pattern and the words it matched) a check recorded in its result's
// `printed` and `quoted`. A record keeps the digest of its text (`reads`), so that a claim recorded as
// a finding or a remark that now holds without it is told apart: a fix changed the text it reads; a
// claim whose text is unchanged changed because something else did (a premise, the harness).

#include <simpson/verify/json.hpp>

#include <string>

namespace simpson::verify {

/// The first 16 hexadecimal digits of the SHA-256 of the texts `printed` ({formulas: [{reference,
/// tex}]}) and `quoted` ([{pattern, text}]) name, in their order; empty when they name none (a claim
/// that reads nothing of the document by formula or sentence: an observation of an experiment, a
/// check of the whole text). The same for a run's result and for a report's claim entry.
std::string reads_digest(const json& printed, const json& quoted);

}  // namespace simpson::verify
