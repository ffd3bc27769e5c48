#pragma once
// report.md to report.html: cmark-gfm (GitHub-flavoured tables), then what a reader of the page
// needs and Markdown cannot say: an id on every heading (GitHub's anchors, so that a link #<claim-id>
// resolves both here and where a forge renders report.md), verdicts coloured, each claim's JSON
// evidence and every long table folded in <details>, and the plots linked from the files beside the
// page (report.html stays small; the report directory is the unit a CI uploads).

#include <string>
#include <string_view>

namespace simpson::verify {

/// Text for HTML or XML (report.html, report.junit.xml): & < > " ' as entities.
std::string markup_escaped(std::string_view text);

/// GitHub's anchor for a heading: lower case, ASCII punctuation other than '-' and '_' dropped,
/// spaces turned into '-' ("phi3-det" stays "phi3-det"; "Notes on claims" is "notes-on-claims").
std::string heading_slug(std::string_view heading_text);

/// Tables with more rows than this are folded in report.html (their summary says how many).
// The paper's claims and the family's members (81 up to s = 6) stay open; work_precision's 400 rows fold.
inline constexpr std::size_t folded_table_rows = 120;

/// The whole page: report.md rendered, with the additions above, under `title`. `katex_beside`:
/// whether katex/ is beside the page (copied from Debian's libjs-katex); without it the page's first
/// paragraph says that its formulas are TeX source, and how to have them rendered.
std::string render_report_html(const std::string& markdown, const std::string& title, bool katex_beside = true);

}  // namespace simpson::verify
