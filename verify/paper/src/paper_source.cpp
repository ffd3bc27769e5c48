#include <simpson/verify/paper_source.hpp>

#include "embedded_paper.hpp"

#include <algorithm>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace simpson::verify {
namespace {

int line_of(const std::string& text, std::size_t offset) {
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
}

/// The math of the display that starts at or before `from` and ends at the next display end.
tex_display display_from(const paper_source& paper, std::size_t from, const std::string& locator) {
  static const char* ends[] = {"\\monendstar", "\\monend", "\\end{equation", "\\end{eqnarray"};
  std::size_t end = std::string::npos;
  for (const char* e : ends) end = std::min(end, paper.text.find(e, from));
  if (end == std::string::npos) {
    throw std::invalid_argument("paper '" + paper.origin + "', " + locator + ": the display has no end");
  }
  std::string tex = paper.text.substr(from, end - from);
  std::replace(tex.begin(), tex.end(), '\n', ' ');
  std::size_t first = from;
  while (first < end && std::isspace(static_cast<unsigned char>(paper.text[first]))) ++first;
  return {locator, line_of(paper.text, first), tex};
}

}  // namespace

std::string without_comments(const std::string& tex) {
  std::string out = tex;
  bool in_comment = false;
  for (std::size_t k = 0; k < out.size(); ++k) {
    if (out[k] == '\n') {
      in_comment = false;
    } else if (in_comment) {
      out[k] = ' ';
    } else if (out[k] == '%' && (k == 0 || out[k - 1] != '\\')) {
      in_comment = true;
      out[k] = ' ';
    }
  }
  return out;
}

paper_source embedded_paper() { return {"embedded", without_comments(embedded_paper_text())}; }

paper_source load_paper(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::invalid_argument("paper '" + path + "': missing or unreadable");
  std::ostringstream text;
  text << in.rdbuf();
  if (!in.good() && !in.eof()) throw std::invalid_argument("paper '" + path + "': cannot be read");
  paper_source paper{path, without_comments(text.str())};
  if (paper.text.find("symplectic scheme") == std::string::npos || paper.text.find("\\label{Phi3}") == std::string::npos) {
    throw std::invalid_argument("paper '" + path +
                                "': not the symplectic Simpson paper (no title 'symplectic scheme' or no \\label{Phi3})");
  }
  return paper;
}

tex_display find_labelled(const paper_source& paper, const std::string& label) {
  const std::string key = "\\label{" + label + "}";
  const std::size_t at = paper.text.find(key);
  if (at == std::string::npos) {
    throw std::invalid_argument("paper '" + paper.origin + "': the label '" + label + "' the ledger needs is not there");
  }
  return display_from(paper, at + key.size(), "label " + label);
}

tex_display find_anchored(const paper_source& paper, const std::string& anchor) {
  const std::size_t at = paper.text.find(anchor);
  if (at == std::string::npos) {
    throw std::invalid_argument("paper '" + paper.origin + "': the anchor '" + anchor + "' the ledger needs is not there");
  }
  static const char* starts[] = {"\\moneqstar", "\\moneq", "\\begin{equation"};
  std::size_t start = std::string::npos, length = 0;
  for (const char* s : starts) {
    const std::size_t found = paper.text.find(s, at);
    if (found < start) {
      start = found;
      length = std::string(s).size();
    }
  }
  if (start == std::string::npos) {
    throw std::invalid_argument("paper '" + paper.origin + "': no display after the anchor '" + anchor + "'");
  }
  return display_from(paper, start + length, "anchor '" + anchor + "'");
}

}  // namespace simpson::verify
