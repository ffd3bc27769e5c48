#pragma once
// A copy of the embedded paper with one change: `from` replaced by `to` at its first place after
// `after` (a label or a phrase). The tests judge such copies to show that a verdict follows the text.

#include <simpson/verify/the_paper.hpp>
#include <simpson/verify/paper_source.hpp>

#include <gtest/gtest.h>

#include <string>

namespace simpson::verify {

inline paper_source altered(const std::string& after, const std::string& from, const std::string& to) {
  paper_source p = embedded_paper();
  const std::size_t start = p.text.find(after);
  EXPECT_NE(start, std::string::npos) << after;
  const std::size_t at = p.text.find(from, start);
  EXPECT_NE(at, std::string::npos) << from;
  replace_text(p, at, from.size(), to);
  p.origin = "altered copy";
  return p;
}

}  // namespace simpson::verify
