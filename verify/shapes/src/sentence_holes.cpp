// The words each hole accepts: see sentence_holes.hpp.

#include <simpson/verify/quoted_sentence.hpp>
#include <simpson/verify/sentence_holes.hpp>

#include <simpson/shapes/proof_shapes.hpp>

#include <fmt/format.h>

#include <stdexcept>

namespace simpson::verify {

const std::vector<sentence_hole>& sentence_holes() {
  static const std::vector<sentence_hole> holes = {
      {"order", hole_reading::number, {}, "the order the sentence states"},
      {"degree", hole_reading::number_or_bound, {}, "the degree of exactness: a number ('degree three': every degree up to it), or a bound ('smaller or equal to 1')"},
      {"modulus", hole_reading::bound, {}, "the roots' modulus the criterion asks; words after the bound may ask them to be simple ('..., those of modulus 1 being simple')"},
      {"product", hole_reading::bound, {}, "the roots' product, a relation and a number with nothing after"},
      {"relation", hole_reading::bound, {}, "the product's sign, a relation to 0 ('smaller than 0', '< 0')"},
      {"from", hole_reading::tex, {}, "the first value of the sum's index, in TeX ('$1$', '$0$')"},
      {"to", hole_reading::tex, {}, "its last value, in TeX ('$N$', '$N-1$')"},
      {"property", hole_reading::property, {}, "the record's `property` word, said or denied"},
      {"emerges", hole_reading::quoted, {}, "how the text says the condition follows from the formula ('naturally emerging')"},
      {"novelty", hole_reading::quoted, {}, "what the text presents as its own ('a variational symplectic numerical method')"},
      {"linearity", hole_reading::phrases,
       {{"linear", "linear"}, {"not linear", "not linear"}, {"nonlinear", "not linear"}, {"non-linear", "not linear"}, {"non linear", "not linear"}},
       "whether the expression is linear in the variables"},
      {"kind", hole_reading::phrases, {{"explicit", "explicit"}, {"implicit", "implicit"}, {"not explicit", "implicit"}},
       "whether the scheme or map is explicit"},
      {"sign", hole_reading::phrases, {{"positive", "positive"}, {"negative", "negative"}}, "a sign (factor-signs: every factor's)"},
      {"roots", hole_reading::phrases,
       {{"conjugate complex", "complex conjugate"}, {"complex conjugate", "complex conjugate"}, {"complex", "complex conjugate"}, {"real", "real"},
        {"distinct real", "real"}, {"real distinct", "real"}},
       "what the characteristic roots are"},
      {"conclusion", hole_reading::phrases, {{"stable", "stable"}, {"unstable", "unstable"}, {"not stable", "unstable"}}, "what the roots make the scheme"},
      {"stability", hole_reading::phrases,
       {{"linearly stable", "stable"}, {"stable", "stable"}, {"unconditionally stable", "unconditionally stable"},
        {"inconditionally stable", "unconditionally stable"}, {"conditionally stable", "conditionally stable"},
        {"conditionnally stable", "conditionally stable"}, {"linearly unstable", "unstable"}, {"unstable", "unstable"}},
       "the scheme's stability ('stable' unqualified: for every step, unless a `qualifier` sentence qualifies it)"},
      {"qualifier", hole_reading::phrases,
       {{"unconditionally", "unconditional"}, {"inconditionally", "unconditional"}, {"conditionally", "conditional"}, {"conditionnally", "conditional"}},
       "for which steps the scheme is stable"},
  };
  return holes;
}

const sentence_hole& hole_named(const std::string& name) {
  for (const sentence_hole& h : sentence_holes()) {
    if (h.name == name) return h;
  }
  throw std::logic_error("sentence holes: no hole named '" + name + "'");
}

std::vector<std::pair<std::string, std::string>> affirmed_or_denied(const std::string& word) {
  return {{word, "affirmed"}, {"not " + word, "denied"}, {"in" + word, "denied"}, {"un" + word, "denied"}, {"non-" + word, "denied"}};
}

namespace {

std::string cell(std::string text) {
  std::string out;
  for (const char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

/// The shapes whose parameters' patterns take the hole {name}.
std::string shapes_taking(const std::string& name) {
  std::string shapes;
  for (const auto& [shape, s] : detail::proof_shapes()) {
    bool takes = false;
    for (const detail::shape_parameter& p : s.parameters) {
      takes = takes || (p.kind == detail::argument_kind::word && (p.hole == name || p.meaning.find("{" + name + "}") != std::string::npos));
    }
    if (takes) shapes += (shapes.empty() ? "`" : ", `") + shape + "`";
  }
  if (name == "property") return "every shape (`says` with `property`)";
  return shapes;
}

std::string words_of(const sentence_hole& h) {
  switch (h.reads) {
    case hole_reading::number:
      return "a number (below)";
    case hole_reading::bound:
      return "a relation, then a number (below): “smaller than 1”, “at most $1$”";
    case hole_reading::number_or_bound:
      return "a relation and a number, or else a number (below)";
    case hole_reading::tex:
      return "a formula in TeX, read as the document's formulas are (its symbols declared)";
    case hole_reading::quoted:
      return "any words: quoted as printed in the finding's one line, not parsed";
    case hole_reading::property: {
      std::string words;
      for (const auto& [phrase, value] : affirmed_or_denied("P")) words += (words.empty() ? "" : ", ") + fmt::format("“{}” ({})", phrase, value);
      return words + ", P the record's `property`";
    }
    case hole_reading::phrases: {
      std::string words;
      for (const auto& [phrase, value] : h.phrases) {
        words += (words.empty() ? "" : ", ") + (phrase == value ? fmt::format("“{}”", phrase) : fmt::format("“{}” ({})", phrase, value));
      }
      return words;
    }
  }
  return {};
}

std::string relation_sign(const std::string& relation) {
  return relation == "<=" ? "≤" : relation == ">=" ? "≥" : relation;
}

}  // namespace

std::string holes_markdown() {
  std::string md = "| hole | in the patterns of | states | the words it accepts (case and white space aside) |\n|---|---|---|---|\n";
  for (const sentence_hole& h : sentence_holes()) {
    md += fmt::format("| `{{{}}}` | {} | {} | {} |\n", h.name, shapes_taking(h.name), cell(h.meaning), words_of(h));
  }
  md += "\nA number: digits (up to six), or a word: ";
  bool first = true;
  for (const auto& [word, value] : number_words()) {
    md += fmt::format("{}{} {}", first ? "" : ", ", word, value);
    first = false;
  }
  md += ". Nothing else (not “a dozen”, not “2nd”).\n\nA relation, tried in this order, then a number as above (a number in `$...$` reads, its TeX dropped): ";
  first = true;
  for (const auto& [phrase, relation] : bound_relations()) {
    md += fmt::format("{}“{}” {}", first ? "" : ", ", cell(phrase), relation_sign(relation));
    first = false;
  }
  return md + ". “one” is a number and “equal to one” a bound; “unity” is neither.\n";
}

}  // namespace simpson::verify
