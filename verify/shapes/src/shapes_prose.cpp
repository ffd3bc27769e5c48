// Shapes of the prose itself: its spelling (Hunspell's dictionary) and its citations (a
// bibliography that resolves them). See shape_support.hpp.

#include <simpson/shapes/shape_support.hpp>

#include <simpson/prove/printed_check_support.hpp>

#include <simpson/verify/paper_provenance.hpp>
#include <simpson/verify/paper_reading.hpp>
#include <simpson/verify/prose_words.hpp>
#include <simpson/verify/quoted_words.hpp>

#include <fmt/format.h>
#include <hunspell/hunspell.hxx>

#include <filesystem>
#include <map>
#include <memory>
#include <set>
#include <algorithm>
#include <cctype>
#include <stdexcept>

namespace simpson::verify::detail {

namespace {

/// Debian's en_US dictionary (hunspell-en-us), where Hunspell's own tools look for it.
std::unique_ptr<Hunspell> english_dictionary() {
  for (const std::string dir : {"/usr/share/hunspell", "/usr/share/myspell/dicts"}) {
    const std::string aff = dir + "/en_US.aff", dic = dir + "/en_US.dic";
    if (std::filesystem::exists(aff) && std::filesystem::exists(dic)) return std::make_unique<Hunspell>(aff.c_str(), dic.c_str());
  }
  return nullptr;
}

/// A word as the dictionary takes it: a possessive's "'s" dropped (Maupertuis's is Maupertuis).
std::string stem(const std::string& word) {
  if (word.size() > 2 && word.compare(word.size() - 2, 2, "'s") == 0) return word.substr(0, word.size() - 2);
  return word;
}

/// A record's "printed: replacement" rule, its printed side split into words.
struct phrase_rule {
  std::vector<std::string> words;
  std::string replacement;
};

std::vector<phrase_rule> phrase_rules(const shape_call& call, const std::string& parameter) {
  std::vector<phrase_rule> rules;
  if (!call.with.count(parameter)) return rules;
  for (const std::string& pair : call.with.at(parameter).values) {
    const std::size_t colon = pair.find(": ");
    if (colon == std::string::npos) throw std::invalid_argument("'" + parameter + "': '" + pair + "' is not 'printed: replacement'");
    phrase_rule rule{{}, pair.substr(colon + 2)};
    std::string word;
    for (const char c : pair.substr(0, colon) + " ") {
      if (c != ' ') {
        word += c;
      } else if (!word.empty()) {
        rule.words.push_back(word);
        word.clear();
      }
    }
    if (rule.words.empty() || rule.replacement.empty()) throw std::invalid_argument("'" + parameter + "': '" + pair + "' is not 'printed: replacement'");
    rules.push_back(std::move(rule));
  }
  return rules;
}

/// Whether the prose's words from `at` on are the phrase's (ASCII letters' case aside: a phrase may
/// open a sentence).
bool phrase_at(const std::vector<prose_word>& words, std::size_t at, const std::vector<std::string>& phrase) {
  if (at + phrase.size() > words.size()) return false;
  for (std::size_t k = 0; k < phrase.size(); ++k) {
    const std::string& a = words[at + k].word;
    const std::string& b = phrase[k];
    if (a.size() != b.size()) return false;
    for (std::size_t c = 0; c < a.size(); ++c) {
      if (std::tolower(static_cast<unsigned char>(a[c])) != std::tolower(static_cast<unsigned char>(b[c]))) return false;
    }
  }
  return true;
}

}  // namespace

/// Every word of the prose (prose_words.hpp) is in Hunspell's en_US dictionary or the record's
/// vocabulary (the document's names and terms of art: symplectic, Newmark). A word that is in
/// neither is a spelling slip, the dictionary's first suggestion what should stand there (or the
/// record's, in a phrase of the record's where that phrase is printed); each slip once, with the
/// lines it is printed on. Real words misused pass a dictionary: the record names their phrases
/// (`misused`), each a slip where the prose prints it. Lexical: no computation is involved.
decider_evidence spelling_shape(const shape_call& call, const run_context& ctx) {
  const paper_reading& paper = paper_of(ctx);
  const std::unique_ptr<Hunspell> dictionary = english_dictionary();
  claim_result result;
  result.reads_whole_text = true;
  if (!dictionary) {
    result.note = "Hunspell's en_US dictionary is not installed (Debian: hunspell-en-us): the spelling is not checked.";
    result.certificate_missing = "a spelling check: no identity";
    decider_evidence e;
    e.reached = decider_evidence::reach::tool_missing;
    e.found = std::move(result);
    return e;
  }
  std::set<std::string> vocabulary;
  if (call.with.count("vocabulary")) {
    for (const std::string& w : call.with.at("vocabulary").values) {
      vocabulary.insert(w);
      dictionary->add(w);  // its capitalised form too, as Hunspell takes a dictionary word
    }
  }
  // The record's own replacements, where the dictionary's first suggestion is not what an English
  // writer would put ("explicited": "made explicit", not "explicated"); a key of several words is a
  // phrase, its replacement taking over the misspelled word where the phrase is printed
  // ("explicited at the relation": "given explicitly by relation").
  std::map<std::string, std::string> replacements;
  std::vector<phrase_rule> context_rules = phrase_rules(call, "suggestions");
  for (auto it = context_rules.begin(); it != context_rules.end();) {
    if (it->words.size() == 1) {
      replacements[it->words.front()] = it->replacement;
      it = context_rules.erase(it);
    } else {
      ++it;
    }
  }
  // Real words misused, named by the record as phrases ("To explicit": "To make explicit"; "can we
  // written": "can be written"): a dictionary passes them, the record's phrase finds them in the prose.
  const std::vector<phrase_rule> misuse_rules = phrase_rules(call, "misused");
  const std::string from = call.with.count("from") ? call.with.at("from").values.front() : std::string();
  const std::vector<prose_word> words = prose_words(paper.source, document_of(ctx), from);
  // Each misspelled word's occurrences: the word, and the replacement where a phrase of the record
  // covers that occurrence (empty: the word's own replacement).
  struct occurrence {
    int line;
    std::string phrase, replacement;
  };
  std::map<std::string, std::vector<occurrence>> slips;
  std::vector<std::string> order;
  for (std::size_t i = 0; i < words.size(); ++i) {
    const prose_word& w = words[i];
    const std::string word = stem(w.word);
    if (dictionary->spell(word) || dictionary->spell(w.word)) continue;
    if (!slips.count(w.word)) order.push_back(w.word);
    occurrence at{w.line, "", ""};
    for (const phrase_rule& rule : context_rules) {
      for (std::size_t k = 0; k < rule.words.size(); ++k) {
        if (k <= i && phrase_at(words, i - k, rule.words)) at = {w.line, fmt::format("{}", fmt::join(rule.words, " ")), rule.replacement};
      }
    }
    slips[w.word].push_back(at);
  }
  json found = json::array();
  std::vector<std::string> corrections;
  const auto lines_of = [](std::vector<int> lines) {  // each line once, in order
    lines.erase(std::unique(lines.begin(), lines.end()), lines.end());
    return lines.size() == 1 ? fmt::format("line {}", lines.front()) : fmt::format("lines {}", fmt::join(lines, ", "));
  };
  for (const std::string& word : order) {
    const std::vector<std::string> suggested = dictionary->suggest(word);
    const auto replaced = replacements.find(word);
    const std::string best = replaced != replacements.end() ? replaced->second : suggested.empty() ? std::string() : suggested.front();
    // The occurrences grouped by what replaces them: the word's own replacement first, then each phrase's.
    std::vector<std::pair<std::string, std::string>> groups;  // printed, replacement
    std::map<std::pair<std::string, std::string>, std::vector<int>> lines;
    std::vector<int> all_lines;
    for (const occurrence& at : slips[word]) {
      const std::pair<std::string, std::string> key = at.phrase.empty() ? std::make_pair(word, best) : std::make_pair(at.phrase, at.replacement);
      if (!lines.count(key)) groups.push_back(key);
      lines[key].push_back(at.line);
      all_lines.push_back(at.line);
    }
    found.push_back({{"word", word}, {"lines", all_lines}, {"suggestions", suggested}});
    if (replaced != replacements.end()) found.back()["replacement"] = replaced->second;
    json in_phrases = json::array();
    for (const auto& key : groups) {
      const std::vector<int>& at = lines[key];
      if (key.first != word) in_phrases.push_back({{"phrase", key.first}, {"lines", at}, {"replacement", key.second}});
      result.amendments.push_back(amendment_in_words(lines_of(at), key.first, key.second.empty() ? "(no suggestion)" : key.second));
      // No line in the correction: the recorded correction guards the words, and an edit elsewhere moves the lines.
      corrections.push_back(fmt::format("{}{}: {}", key.first, at.size() == 1 ? std::string() : fmt::format(" ({} times)", at.size()),
                                        key.second.empty() ? "no suggestion" : key.second));
    }
    if (!in_phrases.empty()) found.back()["in_phrases"] = in_phrases;
  }
  json misused = json::array();
  std::vector<std::string> misuses;
  for (const phrase_rule& rule : misuse_rules) {
    std::vector<int> at;
    for (std::size_t i = 0; i < words.size(); ++i) {
      if (phrase_at(words, i, rule.words)) at.push_back(words[i].line);
    }
    if (at.empty()) continue;  // not printed (or no longer): no slip
    const std::string phrase = fmt::format("{}", fmt::join(rule.words, " "));
    misused.push_back({{"phrase", phrase}, {"lines", at}, {"replacement", rule.replacement}});
    result.amendments.push_back(amendment_in_words(lines_of(at), phrase, rule.replacement));
    misuses.push_back(fmt::format("{}{}: {}", phrase, at.size() == 1 ? std::string() : fmt::format(" ({} times)", at.size()), rule.replacement));
  }
  result.evidence["prose"] = {{"statement", "every word of the prose is in Hunspell's en_US dictionary or the record's vocabulary, and no phrase the record names as a "
                                            "misuse is printed"},
                              {"from", from.empty() ? "the body's start" : from},
                              {"words", words.size()},
                              {"vocabulary", vocabulary},
                              {"dictionary", "Hunspell 1.7, en_US (Debian's hunspell-en-us); suggestions are Hunspell's, first first"},
                              {"not_in_dictionary", found},
                              {"misused", misused}};
  result.evidence["lexical"] = "the verdict follows from the words as printed; no computation is involved";
  result.certificate_missing = "a spelling check: no identity to state";
  decider_evidence e;
  e.statement = "the prose's spelling";
  e.lexical = answer_of(order.empty() && misuses.empty());
  if (order.empty() && misuses.empty()) {
    result.note = fmt::format("Lexical: every one of the {} words of the prose is in the dictionary or the vocabulary{}.", words.size(),
                              misuse_rules.empty() ? "" : ", and no phrase the record names as a misuse is printed");
    e.found = std::move(result);
    return e;
  }
  std::vector<std::string> said;
  if (!order.empty()) {
    said.push_back(fmt::format("{} word{} not in the dictionary, with {}: {}", order.size(), order.size() == 1 ? "" : "s",
                               replacements.empty() && context_rules.empty() ? "Hunspell's first suggestion" : "Hunspell's first suggestion or the record's replacement",
                               fmt::join(corrections, "; ")));
  }
  if (!misuses.empty()) {
    said.push_back(fmt::format("{} phrase{} of dictionary words misused: {}", misuses.size(), misuses.size() == 1 ? "" : "s", fmt::join(misuses, "; ")));
  }
  result.correction = fmt::format("{}", fmt::join(said, "; and "));
  result.note = fmt::format("Lexical: {} of the {} words of the prose {} in neither Hunspell's en_US dictionary nor the record's vocabulary{}. A "
                            "misuse of real words is found only where the record names its phrase{}.",
                            order.size(), words.size(), order.size() == 1 ? "is" : "are",
                            misuses.empty() ? "" : fmt::format(", and {} phrase{} the record names as a misuse {} printed", misuses.size(),
                                                               misuses.size() == 1 ? "" : "s", misuses.size() == 1 ? "is" : "are"),
                            misuse_rules.empty() ? " (none named here: 'can we written' would pass)" : "");
  e.found = std::move(result);
  return e;
}

/// Every \cite key of the live text is resolved by the source's bibliography (a \bibitem); when one
/// is not, what the citations attribute cannot be checked: unverifiable, one finding for all of them.
decider_evidence citations_shape(const shape_call&, const run_context& ctx) {
  const paper_reading& paper = paper_of(ctx);
  const paper_provenance p = read_provenance(paper.source);
  claim_result result;
  result.reads_whole_text = true;
  json uses = json::array();
  std::set<std::string> keys;
  for (const citation_use& c : p.citations) {
    uses.push_back({{"key", c.key}, {"line", c.line}});
    keys.insert(c.key);
  }
  result.evidence["citations"] = {{"uses", uses}, {"keys", keys.size()}, {"bibliography", p.bibliography}, {"unresolved", p.unresolved}};
  result.certificate_missing = "a bibliography's presence: no identity to state";
  decider_evidence e;
  e.statement = "the citations' entries";
  e.lexical = answer_of(p.unresolved.empty());
  e.if_false = verdict::unverifiable;  // what the citations attribute cannot be checked
  if (p.unresolved.empty()) {
    result.note = fmt::format("Each of the {} citations ({} keys) has its entry in the source's bibliography.", p.citations.size(), keys.size());
    e.found = std::move(result);
    return e;
  }
  result.note = fmt::format("{} of the {} citation keys ({} uses) are unresolved: the source carries {}. What they attribute cannot be checked.",
                            p.unresolved.size(), keys.size(), p.citations.size(), p.bibliography ? "no entry for them" : "no bibliography");
  // No "printed X, should be Y": material absent from the source given is no slip of the text (its
  // printed edition may well have its references).
  e.found = std::move(result);
  return e;
}

/// The shapes of this file, each one's name, summary, principal argument and parameters beside the
/// function that decides it (proof_shapes.cpp lists the files).
std::vector<proof_shape> prose_shape_specs() {
  std::vector<proof_shape> all;
  const auto add = [&](proof_shape s) { all.push_back(std::move(s)); };
  add({"spelling", "every word of the document's prose is in Hunspell's en_US dictionary or the record's vocabulary (its names and terms of art), "
       "and no phrase the record names as a misuse of real words is printed", "",
       {{"vocabulary", argument_kind::words, false, "words the dictionary lacks that the document spells right: names, terms of art ('symplectic')"},
        {"from", argument_kind::word, false, "where the prose checked starts: words the source prints ('Abstract'); the body's start without it"},
        {"suggestions", argument_kind::words, false,
         "the record's replacement for a slip, where the dictionary's first suggestion is not what an English writer puts there "
         "('explicited: made explicit'); a key of several words is a phrase whose replacement takes over the word where it is printed "
         "('explicited at the relation: given explicitly by relation')",
         0, "", false, {}, "", "", "", "", "", true},
        {"misused", argument_kind::words, false,
         "phrases of dictionary words the record names as a misuse, each 'printed: replacement' ('To explicit: To make explicit', 'can we "
         "written: can be written'): a slip wherever the prose prints it",
         0, "", false, {}, "", "", "", "", "", true}},
       spelling_shape});
  add({"citations", "every \\cite key of the document has its entry in the document's bibliography; unverifiable when one has none", "", {},
       citations_shape});
  return all;
}

}  // namespace simpson::verify::detail
