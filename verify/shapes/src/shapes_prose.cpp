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

}  // namespace

/// Every word of the prose (prose_words.hpp) is in Hunspell's en_US dictionary or the record's
/// vocabulary (the document's names and terms of art: symplectic, Newmark). A word that is in
/// neither is a spelling slip, the dictionary's first suggestion what should stand there; each
/// slip once, with the lines it is printed on. Lexical by nature: no computation is involved.
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
  // writer would put ("explicited": "made explicit", not "explicated").
  std::map<std::string, std::string> replacements;
  if (call.with.count("suggestions")) {
    for (const std::string& pair : call.with.at("suggestions").values) {
      const std::size_t colon = pair.find(": ");
      replacements[pair.substr(0, colon)] = pair.substr(colon + 2);
    }
  }
  const std::string from = call.with.count("from") ? call.with.at("from").values.front() : std::string();
  const std::vector<prose_word> words = prose_words(paper.source, document_of(ctx), from);
  std::map<std::string, std::vector<int>> slips;  // word: its lines
  std::vector<std::string> order;
  for (const prose_word& w : words) {
    const std::string word = stem(w.word);
    if (dictionary->spell(word) || dictionary->spell(w.word)) continue;
    if (!slips.count(w.word)) order.push_back(w.word);
    slips[w.word].push_back(w.line);
  }
  json found = json::array();
  std::vector<std::string> corrections;
  for (const std::string& word : order) {
    const std::vector<std::string> suggested = dictionary->suggest(word);
    const auto replaced = replacements.find(word);
    const std::string best = replaced != replacements.end() ? replaced->second : suggested.empty() ? std::string() : suggested.front();
    json lines = slips[word];
    found.push_back({{"word", word}, {"lines", lines}, {"suggestions", suggested}});
    if (replaced != replacements.end()) found.back()["replacement"] = replaced->second;
    const std::string where = slips[word].size() == 1 ? fmt::format("line {}", slips[word].front()) : fmt::format("lines {}", fmt::join(slips[word], ", "));
    result.amendments.push_back(amendment_in_words(where, word, best.empty() ? "(no suggestion)" : best));
    // No line in the correction: the recorded correction guards the words, and an edit elsewhere moves the lines.
    const std::size_t times = slips[word].size();
    corrections.push_back(fmt::format("{}{}: {}", word, times == 1 ? std::string() : fmt::format(" ({} times)", times), best.empty() ? "no suggestion" : best));
  }
  result.evidence["prose"] = {{"statement", "every word of the prose is in Hunspell's en_US dictionary or the record's vocabulary"},
                              {"from", from.empty() ? "the body's start" : from},
                              {"words", words.size()},
                              {"vocabulary", vocabulary},
                              {"dictionary", "Hunspell 1.7, en_US (Debian's hunspell-en-us); suggestions are Hunspell's, first first"},
                              {"not_in_dictionary", found}};
  result.evidence["lexical"] = "the verdict follows from the words as printed; no computation is involved";
  result.certificate_missing = "a spelling check: no identity to state";
  decider_evidence e;
  e.statement = "the prose's spelling";
  e.lexical = answer_of(order.empty());
  if (order.empty()) {
    result.note = fmt::format("Lexical: every one of the {} words of the prose is in the dictionary or the vocabulary.", words.size());
    e.found = std::move(result);
    return e;
  }
  result.correction = fmt::format("{} word{} not in the dictionary, with {}: {}", order.size(), order.size() == 1 ? "" : "s",
                                  replacements.empty() ? "Hunspell's first suggestion" : "Hunspell's first suggestion or the record's replacement",
                                  fmt::join(corrections, "; "));
  result.note = fmt::format("Lexical: {} of the {} words of the prose are in neither Hunspell's en_US dictionary nor the record's vocabulary. A "
                            "grammatical slip of real words ('can we written') is beyond a dictionary.",
                            order.size(), words.size());
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
  add({"spelling", "every word of the document's prose is in Hunspell's en_US dictionary or the record's vocabulary (its names and terms of art)", "",
       {{"vocabulary", argument_kind::words, false, "words the dictionary lacks that the document spells right: names, terms of art ('symplectic')"},
        {"from", argument_kind::word, false, "where the prose checked starts: words the source prints ('Abstract'); the body's start without it"},
        {"suggestions", argument_kind::words, false,
         "the record's replacement for a slip, where the dictionary's first suggestion is not what an English writer puts there "
         "('explicited: made explicit')",
         0, "", false, {}, "", "", "", "", "", true}},
       spelling_shape});
  add({"citations", "every \\cite key of the document has its entry in the document's bibliography; unverifiable when one has none", "", {},
       citations_shape});
  return all;
}

}  // namespace simpson::verify::detail
