#pragma once
// What text a run checked, and what is missing from it: the title and the edition line the source
// prints, its SHA-256, the citations it makes and whether a bibliography resolves them; and the
// earlier text the source keeps in its comments (a display commented out above the live one with
// the same \label), so that it can be checked like the live text.

#include <simpson/verify/paper_source.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

/// One \cite key where the live text uses it.
struct citation_use {
  std::string key;
  int line = 0;
};

struct paper_provenance {
  std::string title;    // the \LARGE lines of the title page, joined
  std::string edition;  // the sentence of the live text that begins with "Edition", as printed
  int edition_line = 0; // 0 when the source prints none
  std::string sha256;
  std::vector<citation_use> citations;   // every key of every \cite of the live text, in order
  bool bibliography = false;             // a \bibliography{..}, thebibliography or \bibitem in the live text
  std::vector<std::string> unresolved;   // keys no \bibitem of the live text defines (every key without a bibliography)
};

/// Reads the provenance from the source's live text (comments excluded).
paper_provenance read_provenance(const paper_source& paper);

/// The \cite keys of the sentence that holds a quoted span (`span_text`, white space aside, found
/// from the start of line `line`): the attribution the sentence makes. A sentence ends at a full
/// stop followed by white space ("et al.}" does not end one).
std::vector<std::string> citations_in_sentence(const paper_source& paper, int line, const std::string& span_text);

/// A display kept in the comments: its \label and the line of its first line in the source, and the
/// block uncommented (from "\begin{equation}\label{...}", or a macro of the source that opens one,
/// to its end).
struct earlier_display {
  std::string label;
  int line = 0;
  std::string tex;
};

/// Every display the source keeps commented out ("%" before each of its lines) that carries a \label
/// the live text also has: an earlier version of that display.
std::vector<earlier_display> commented_displays(const paper_source& paper);

/// The source with the live display of `earlier.label` replaced by the earlier one (line numbers
/// kept): the earlier text, to be read and checked like the live one.
paper_source with_earlier_display(const paper_source& paper, const earlier_display& earlier);

}  // namespace simpson::verify
