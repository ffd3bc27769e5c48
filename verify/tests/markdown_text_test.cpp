// What GiNaC and the paper's TeX print reaches report.html as printed: no '*' read as emphasis, no
// D[0](V)(q) read as a link, no raw HTML; headings get GitHub's anchors.

#include <simpson/verify/markdown_text.hpp>
#include <simpson/verify/report_html.hpp>

#include <gtest/gtest.h>

#include <string>

namespace simpson::verify {
namespace {

std::string html_text(std::string text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

TEST(MarkdownText, GinacOutputRendersVerbatim) {
  for (const std::string expr : {"(D[0](V)(q_m)*h^2-8*m*q_m+4*m*q_l)/(h^2)", "-3*beta^3*gamma^3-9*alpha^2*beta*delta^2*gamma",
                                 "d^6q/dt^5*h^6+6*d^5q/dt^5*h^5", "a <b>x</b> & ~~y~~ _z_ `w` [1](2) ![i](j) \\* |p|"}) {
    const std::string html = render_report_html(markdown_escaped(expr) + "\n", "t");
    EXPECT_NE(html.find("<p>" + html_text(expr) + "</p>"), std::string::npos) << expr << "\n" << html;
    const std::string code = render_report_html(markdown_code(expr) + "\n", "t");
    EXPECT_NE(code.find("<code>" + html_text(expr) + "</code>"), std::string::npos) << expr << "\n" << code;
  }
}

TEST(MarkdownText, TableCellsStayOneCell) {
  const std::string md = "| a | b |\n|---|---|\n| " + markdown_escaped("x|y*z\nw") + " | 2 |\n";
  const std::string html = render_report_html(md, "t");
  EXPECT_NE(html.find("<td>x|y*z w</td>"), std::string::npos) << html;
}

TEST(MarkdownText, CodeSpansHoldBackticks) {
  EXPECT_EQ(markdown_code("a`b"), "``a`b``");
  EXPECT_EQ(markdown_code("`x"), "`` `x ``");
  const std::string html = render_report_html(markdown_code("`x") + "\n", "t");
  EXPECT_NE(html.find("<code>`x</code>"), std::string::npos) << html;
}

TEST(ReportHtml, HeadingsHaveGithubAnchorsAndLinksResolve) {
  EXPECT_EQ(heading_slug("phi3-det"), "phi3-det");
  EXPECT_EQ(heading_slug("Notes on claims that hold"), "notes-on-claims-that-hold");
  EXPECT_EQ(heading_slug("gamma-system (§7, prose)"), "gamma-system-§7-prose");
  const std::string html = render_report_html("[go](#phi3-det)\n\n### phi3-det\n\n### phi3-det\n", "t");
  EXPECT_NE(html.find("<h3 id=\"phi3-det\">"), std::string::npos) << html;
  EXPECT_NE(html.find("<h3 id=\"phi3-det-1\">"), std::string::npos) << html;
}

TEST(ReportHtml, VerdictsAreColouredAndLongTablesFolded) {
  std::string md = "**holds** **erratum** **fails**\n\n| n |\n|---|\n";
  for (std::size_t k = 0; k <= folded_table_rows; ++k) md += "| " + std::to_string(k) + " |\n";
  const std::string html = render_report_html(md, "t");
  for (const char* v : {"holds", "erratum", "fails"}) {
    EXPECT_NE(html.find(std::string("class=\"verdict verdict-") + v + "\""), std::string::npos) << v;
  }
  EXPECT_NE(html.find("<details><summary>table of " + std::to_string(folded_table_rows + 1) + " rows"), std::string::npos);
}

}  // namespace
}  // namespace simpson::verify
