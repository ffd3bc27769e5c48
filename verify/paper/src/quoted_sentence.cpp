// The words of a quoted sentence: see quoted_sentence.hpp.

#include <simpson/verify/quoted_sentence.hpp>

#include <algorithm>
#include <cctype>
#include <map>

namespace simpson::verify {
namespace {

std::string lower(std::string s) {
  std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return s;
}

/// "three", "third", "3" → 3; -1 when the word is none of them.
int number_word(const std::string& word) {
  const std::string w = lower(word);
  if (!w.empty() && w.size() <= 6 && std::all_of(w.begin(), w.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
    return std::stoi(w);
  }
  for (const auto& [name, value] : number_words()) {
    if (name == w) return value;
  }
  return -1;
}

}  // namespace

const std::vector<std::pair<std::string, int>>& number_words() {
  static const std::vector<std::pair<std::string, int>> words = {
      {"zero", 0},    {"one", 1},       {"first", 1},   {"two", 2},      {"second", 2},   {"three", 3},   {"third", 3},
      {"four", 4},    {"fourth", 4},    {"five", 5},    {"fifth", 5},    {"six", 6},      {"sixth", 6},   {"seven", 7},
      {"seventh", 7}, {"eight", 8},     {"eighth", 8},  {"nine", 9},     {"ninth", 9},    {"ten", 10},    {"tenth", 10},
      {"eleven", 11}, {"eleventh", 11}, {"twelve", 12}, {"twelfth", 12}};
  return words;
}

const std::vector<std::pair<std::string, std::string>>& bound_relations() {
  static const std::vector<std::pair<std::string, std::string>> relations = {
      {"smaller than or equal to", "<="}, {"smaller or equal to", "<="}, {"less than or equal to", "<="}, {"less or equal to", "<="},
      {"not greater than", "<="},         {"at most", "<="},             {"\\leq", "<="},                  {"\\le", "<="},
      {"<=", "<="},                       {"smaller than", "<"},         {"less than", "<"},               {"<", "<"},
      {"equal to", "="},                  {"=", "="},                    {"greater than or equal to", ">="}, {"greater or equal to", ">="},
      {"at least", ">="},                 {"\\geq", ">="},               {"\\ge", ">="},                   {">=", ">="},
      {"greater than", ">"},              {">", ">"}};
  return relations;
}

bool stated_bound::admits(int x) const {
  if (relation == "<") return x < value;
  if (relation == "<=") return x <= value;
  if (relation == "=") return x == value;
  if (relation == ">=") return x >= value;
  return x > value;
}

quoted_sentence::quoted_sentence(prose_span span, std::string origin, json* records, std::size_t index)
    : span_(std::move(span)), origin_(std::move(origin)), records_(records), index_(index) {}

std::string quoted_sentence::words(const std::string& hole) const {
  const auto it = span_.holes.find(hole);
  if (it == span_.holes.end()) throw std::logic_error("quoted sentence: the pattern has no hole '" + hole + "'");
  return plain_words(it->second);
}

void quoted_sentence::record(const std::string& hole, const json& parsed) const {
  if (records_ != nullptr) (*records_)[index_]["parsed"][hole] = parsed;
}

void quoted_sentence::unparsed(const std::string& hole, const std::string& expected) const {
  throw text_changed("document '" + origin_ + "', line " + std::to_string(span_.line) + ": the words '" + words(hole) +
                     "' do not parse as " + expected + " (in: " + span_.text + ")");
}

int quoted_sentence::number(const std::string& hole) const {
  const int n = number_word(words(hole));
  if (n < 0) unparsed(hole, "a number (digits, or a word up to twelve)");
  record(hole, n);
  return n;
}

stated_bound quoted_sentence::bound(const std::string& hole) const {
  const std::string w = lower(words(hole));
  for (const auto& [phrase, relation] : bound_relations()) {
    if (w.rfind(phrase, 0) != 0) continue;
    std::string rest = w.substr(phrase.size());
    rest.erase(0, rest.find_first_not_of(' '));
    const std::size_t end = std::min(rest.find_first_of(" ,;"), rest.size());
    const int n = number_word(rest.substr(0, end));
    if (n < 0) break;
    std::string after = rest.substr(end);
    after.erase(0, after.find_first_not_of(" ,;"));
    record(hole, {{"relation", relation}, {"bound", n}, {"rest", after}});
    return {relation, n, after};
  }
  unparsed(hole, "a relation and a bound (such as 'smaller than 1' or 'smaller or equal to 1')");
}

std::string quoted_sentence::choice(const std::string& hole, const std::vector<std::pair<std::string, std::string>>& phrases) const {
  const std::string w = lower(words(hole));
  std::string known;
  for (const auto& [phrase, value] : phrases) {
    if (w == lower(phrase)) {
      record(hole, value);
      return value;
    }
    known += (known.empty() ? "'" : ", '") + phrase + "'";
  }
  unparsed(hole, "one of " + known);
}

std::string quoted_sentence::containing(const std::string& hole, const std::vector<std::pair<std::string, std::string>>& keys) const {
  const std::string w = lower(words(hole));
  std::string known;
  for (const auto& [key, value] : keys) {
    if (w.find(lower(key)) != std::string::npos) {
      record(hole, value);
      return value;
    }
    known += (known.empty() ? "'" : ", '") + key + "'";
  }
  unparsed(hole, "words containing one of " + known);
}

quoted_sentence quote_sentence(const paper_source& paper, const std::string& pattern, json* quotes) {
  const std::optional<prose_span> span = find_prose(paper, pattern);
  if (!span) {
    if (quotes != nullptr) quotes->push_back({{"source", paper.origin}, {"pattern", pattern}, {"found", false}});
    throw text_changed("document '" + paper.origin + "': the sentence the claim judges is no longer there (looked for: " + pattern + ")");
  }
  if (!span->also_at.empty()) {
    std::string lines = std::to_string(span->line);
    for (const int line : span->also_at) lines += ", " + std::to_string(line);
    if (quotes != nullptr) quotes->push_back({{"source", paper.origin}, {"pattern", pattern}, {"found", false}, {"ambiguous", lines}});
    throw text_changed("document '" + paper.origin + "': the pattern matches " + std::to_string(span->also_at.size() + 1) +
                       " spans (lines " + lines + "), so it does not say which sentence the claim judges; lengthen it until it matches one (" +
                       pattern + ")");
  }
  std::size_t index = 0;
  if (quotes != nullptr) {
    json words = json::object();
    for (const auto& [hole, text] : span->holes) words[hole] = plain_words(text);
    index = quotes->size();
    quotes->push_back({{"source", paper.origin}, {"line", span->line}, {"text", span->text}, {"pattern", pattern},
                       {"found", true}, {"words", words}, {"parsed", json::object()}});
  }
  return {*span, paper.origin, quotes, index};
}

}  // namespace simpson::verify
