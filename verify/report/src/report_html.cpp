#include <simpson/verify/report_html.hpp>
#include <simpson/verify/verdict.hpp>

#include <cmark-gfm-core-extensions.h>
#include <cmark-gfm.h>
#include <fmt/format.h>

#include <cctype>
#include <cstdlib>
#include <map>
#include <memory>

namespace simpson::verify {
namespace {

/// Markdown to HTML by cmark-gfm with GitHub's table, strikethrough and autolink extensions. Raw
/// HTML is left out (CMARK_OPT_DEFAULT): every text the report puts into Markdown is escaped.
std::string cmark_html(const std::string& markdown) {
  cmark_gfm_core_extensions_ensure_registered();
  const std::unique_ptr<cmark_parser, decltype(&cmark_parser_free)> parser(cmark_parser_new(CMARK_OPT_DEFAULT),
                                                                           cmark_parser_free);
  for (const char* name : {"table", "strikethrough", "autolink"}) {
    if (cmark_syntax_extension* ext = cmark_find_syntax_extension(name)) cmark_parser_attach_syntax_extension(parser.get(), ext);
  }
  cmark_parser_feed(parser.get(), markdown.data(), markdown.size());
  cmark_node* document = cmark_parser_finish(parser.get());
  char* rendered = cmark_render_html(document, CMARK_OPT_DEFAULT, cmark_parser_get_syntax_extensions(parser.get()));
  std::string body(rendered);
  std::free(rendered);
  cmark_node_free(document);
  return body;
}

/// The text of an HTML fragment: tags dropped, the entities cmark writes decoded.
std::string text_of(std::string_view html) {
  std::string text;
  bool in_tag = false;
  for (const char c : html) {
    if (c == '<') in_tag = true;
    else if (c == '>') in_tag = false;
    else if (!in_tag) text += c;
  }
  for (const auto& [entity, c] : {std::pair<std::string_view, char>{"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}}) {
    for (std::size_t at; (at = text.find(entity)) != std::string::npos;) text.replace(at, entity.size(), 1, c);
  }
  return text;
}

void replace_all(std::string& text, std::string_view from, std::string_view to) {
  for (std::size_t at = 0; (at = text.find(from, at)) != std::string::npos; at += to.size()) text.replace(at, from.size(), to);
}

/// <hN> gets id="<slug>", the slug made unique as GitHub does (a second "x" is "x-1").
std::string with_heading_ids(const std::string& html) {
  std::map<std::string, int> seen;
  std::string out;
  std::size_t at = 0;
  for (std::size_t found; (found = html.find("<h", at)) != std::string::npos;) {
    const char level = found + 2 < html.size() ? html[found + 2] : '\0';
    if (level < '1' || level > '6' || found + 3 >= html.size() || html[found + 3] != '>') {
      out += html.substr(at, found + 2 - at);
      at = found + 2;
      continue;
    }
    const std::string close = fmt::format("</h{}>", level);
    const std::size_t end = html.find(close, found);
    std::string slug = heading_slug(text_of(html.substr(found + 4, end - found - 4)));
    const int n = seen[slug]++;
    if (n > 0) slug += "-" + std::to_string(n);
    out += html.substr(at, found - at) + fmt::format("<h{} id=\"{}\">", level, slug);
    at = found + 4;
  }
  return out + html.substr(at);
}

/// The page's table of contents: a link to each <h2>, after the first <h1> (or at the top).
std::string with_contents(const std::string& html) {
  std::string items;
  for (std::size_t at = html.find("<h2 id=\""); at != std::string::npos; at = html.find("<h2 id=\"", at + 1)) {
    const std::size_t id_end = html.find('"', at + 8), end = html.find("</h2>", at);
    if (id_end == std::string::npos || end == std::string::npos) break;
    const std::string id = html.substr(at + 8, id_end - at - 8), text = text_of(html.substr(id_end + 2, end - id_end - 2));
    items += fmt::format("<li><a href=\"#{}\">{}</a></li>", id, markup_escaped(text));
  }
  if (items.empty()) return html;
  const std::string nav = "<nav class=\"contents\"><strong>Contents</strong><ul>" + items + "</ul></nav>\n";
  const std::size_t h1 = html.find("</h1>");
  return h1 == std::string::npos ? nav + html : html.substr(0, h1 + 5) + "\n" + nav + html.substr(h1 + 5);
}

/// Inline code that is TeX (a backslash before a letter) gets class "tex": the page renders it with
/// KaTeX when katex/ is beside it (report_directory.cpp copies Debian's), and shows the TeX as code
/// where KaTeX is missing or does not read it (a quote cut short).
std::string with_tex_marked(const std::string& html) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t found; (found = html.find("<code>", at)) != std::string::npos;) {
    const std::size_t end = html.find("</code>", found);
    if (end == std::string::npos) break;
    bool tex = false;
    for (std::size_t k = found + 6; k + 1 < end && !tex; ++k) tex = html[k] == '\\' && std::isalpha(static_cast<unsigned char>(html[k + 1]));
    const bool in_pre = found >= 5 && html.compare(found - 5, 5, "<pre>") == 0;
    out += html.substr(at, found - at) + (tex && !in_pre ? "<code class=\"tex\">" : "<code>");
    at = found + 6;
  }
  return out + html.substr(at);
}

/// KaTeX from katex/ beside the page, no network: each code.tex replaced by its rendering (the TeX
/// kept as the rendering's title), left as code when KaTeX throws.
constexpr const char* katex_script =
    "<script src=\"katex/katex.min.js\"></script>\n"
    "<script>if(window.katex){document.querySelectorAll('code.tex').forEach(function(c){"
    "var s=document.createElement('span');s.className='tex-rendered';s.title=c.textContent;"
    "try{katex.render(c.textContent,s,{throwOnError:true});c.replaceWith(s);}catch(e){}});}</script>\n";

/// Tables of more than folded_table_rows rows inside <details>, closed, with their row count.
std::string with_long_tables_folded(const std::string& html) {
  std::string out;
  std::size_t at = 0;
  for (std::size_t found; (found = html.find("<table>", at)) != std::string::npos;) {
    const std::size_t end = html.find("</table>", found) + 8;
    const std::string table = html.substr(found, end - found);
    std::size_t rows = 0;
    for (std::size_t tr = table.find("<tr>"); tr != std::string::npos; tr = table.find("<tr>", tr + 4)) ++rows;
    rows = rows > 0 ? rows - 1 : 0;  // the header row
    out += html.substr(at, found - at);
    // Each table scrolls inside the page's width: a wide one never widens the page.
    const std::string wrapped = "<div class=\"table-wrap\">" + table + "</div>";
    out += rows > folded_table_rows ? fmt::format("<details><summary>table of {} rows (unfold)</summary>\n{}\n</details>", rows, wrapped)
                                    : wrapped;
    at = end;
  }
  return out + html.substr(at);
}

constexpr const char* style =
    "body{font-family:sans-serif;max-width:1200px;margin:2em auto;padding:0 1em;line-height:1.4}"
    "table{border-collapse:collapse;font-size:90%}td,th{border:1px solid #ccc;padding:2px 6px}"
    "pre{background:#f6f6f6;padding:8px;overflow-x:auto;font-size:85%}img{max-width:100%}"
    "summary{cursor:pointer;color:#555}"
    "td,li,p{overflow-wrap:break-word}code{overflow-wrap:anywhere}.table-wrap{overflow-x:auto;max-width:100%}"
    ".tex-rendered{display:inline-block;position:relative;max-width:100%;overflow-x:auto;overflow-y:hidden;vertical-align:middle}"
    ".contents{background:#f6f6f6;padding:6px 12px;margin:1em 0}.contents ul{columns:2;margin:4px 0}"
    ".verdict{padding:0 4px;border-radius:3px}"
    ".verdict-holds{background:#dff0d8;color:#1e5e1e}.verdict-erratum{background:#fcf3cf;color:#7a5a00}"
    ".verdict-fails{background:#f8d7da;color:#842029}.verdict-kernels-disagree{background:#842029;color:#fff}"
    ".verdict-text-changed{background:#6f42c1;color:#fff}.verdict-undecided{background:#fff3cd;color:#664d03}"
    ".verdict-unproved{background:#fff3cd;color:#664d03}.verdict-skipped{background:#e2e3e5;color:#41464b}"
    ".verdict-unverifiable{background:#e2e3e5;color:#41464b;font-style:italic}"
    ".verdict-unexpected{outline:2px solid #c00}"
    ".no-katex{background:#fff3cd;border:1px solid #c9a400;padding:6px 10px}";

}  // namespace

std::string markup_escaped(std::string_view text) {
  std::string out;
  for (const char c : text) {
    switch (c) {
      case '&': out += "&amp;"; break;
      case '<': out += "&lt;"; break;
      case '>': out += "&gt;"; break;
      case '"': out += "&quot;"; break;
      case '\'': out += "&apos;"; break;
      default: out += c;
    }
  }
  return out;
}

std::string heading_slug(std::string_view heading_text) {
  std::string slug;
  for (const char c : heading_text) {
    const auto u = static_cast<unsigned char>(c);
    if (u >= 0x80 || std::isalnum(u) || c == '-' || c == '_') slug += static_cast<char>(std::tolower(u));
    else if (c == ' ') slug += '-';
  }
  return slug;
}

std::string render_report_html(const std::string& markdown, const std::string& title, bool katex_beside) {
  std::string body = with_tex_marked(with_contents(with_long_tables_folded(with_heading_ids(cmark_html(markdown)))));
  // Verdicts: report.md writes them in bold; each gets its colour.
  for (const verdict_meaning& m : verdict_meanings) {
    replace_all(body, fmt::format("<strong>{}</strong>", m.name), fmt::format("<strong class=\"verdict verdict-{}\">{}</strong>", m.name, m.name));
  }
  replace_all(body, "<strong>(unexpected)</strong>", "<strong class=\"verdict verdict-unexpected\">(unexpected)</strong>");
  // Each claim's evidence JSON, folded.
  replace_all(body, "<pre><code class=\"language-json\">", "<details><summary>evidence (JSON)</summary><pre><code class=\"language-json\">");
  std::string out;
  std::size_t at = 0;
  for (std::size_t found; (found = body.find("<details><summary>evidence (JSON)", at)) != std::string::npos;) {
    const std::size_t end = body.find("</code></pre>", found) + 13;
    out += body.substr(at, end - at) + "</details>";
    at = end;
  }
  body = out + body.substr(at);
  // Links between the report's pages go to their HTML renderings.
  replace_all(body, "href=\"timing.md\"", "href=\"timing.html\"");
  replace_all(body, "href=\"report.md\"", "href=\"report.html\"");
  // Without KaTeX beside the page the formulas stay TeX: the page says so first, and how to fix it.
  const std::string no_katex =
      katex_beside ? std::string()
                   : "<p class=\"no-katex\"><strong>The formulas on this page are shown as TeX source, not rendered:</strong> KaTeX (Debian's "
                     "package libjs-katex) was not installed when this report was written, so no katex/ folder is beside it. Install it "
                     "(<code>apt-get install libjs-katex</code>, or <code>scripts/install-deps verify</code>) and run simpson-verify again.</p>\n";
  return "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" + markup_escaped(title) + "</title>\n" +
         (katex_beside ? "<link rel=\"stylesheet\" href=\"katex/katex.min.css\">\n" : "") + "<style>" + style + "</style>\n</head>\n<body>\n" +
         no_katex + body + (katex_beside ? katex_script : "") + "</body>\n</html>\n";
}

}  // namespace simpson::verify
