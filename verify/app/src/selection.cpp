#include <simpson/verify/selection.hpp>

#include <simpson/verify/ledger.hpp>

#include <algorithm>
#include <stdexcept>

#include <fnmatch.h>  // --claims patterns (POSIX)

namespace simpson::verify {
namespace {

std::string trimmed(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

/// The precisions a section the scene does not define runs in: the scene's floating precisions, or
/// double.
std::vector<precision> floating_precisions(const scene& s) {
  std::vector<precision> out;
  for (const precision& p : s.precisions) {
    if (!p.exact()) out.push_back(p);
  }
  if (out.empty()) out.push_back(precision::parse("double"));
  return out;
}

void keep_sections(scene& s, const std::vector<std::string>& names, const std::vector<const experiment_section*>& registry) {
  experiment_settings& e = s.experiments;
  for (const experiment_section* section : registry) {
    const bool wanted = std::find(names.begin(), names.end(), section->name()) != names.end();
    if (!wanted) e.remove(section->name());
    else if (!e.has(section->name())) e.set(*section, section->defaults(floating_precisions(s)), registry);
  }
}

}  // namespace

std::vector<std::string> section_names(const std::vector<const experiment_section*>& registry) {
  std::vector<std::string> names;
  for (const experiment_section* section : registry) names.push_back(section->name());
  return names;
}

void apply_selection(scene& s, const scene_selection& selection, const claim_book& book) {
  if (!selection.claims && !selection.sections) return;
  std::vector<std::string> parts;
  if (selection.claims) {
    std::vector<std::string> ids;
    for (const std::string& given : *selection.claims) {
      const std::string id = trimmed(given);
      if (id.empty()) continue;
      if (id == "all") {  // the scene's own claims
        for (const std::string& own : s.claims) {
          if (std::find(ids.begin(), ids.end(), own) == ids.end()) ids.push_back(own);
        }
        continue;
      }
      if (id.find_first_of("*?[") != std::string::npos) {  // a pattern, as test runners take them: gamma-*
        bool matched = false;
        for (const claim& c : book.claims) {
          if (fnmatch(id.c_str(), c.id.c_str(), 0) != 0) continue;
          matched = true;
          if (std::find(ids.begin(), ids.end(), c.id) == ids.end()) ids.push_back(c.id);
        }
        if (!matched) throw std::invalid_argument("--claims: the pattern '" + id + "' matches no claim id (see --list-claims)");
        continue;
      }
      const std::string& known = book.find(id).id;  // throws std::invalid_argument naming an unknown id
      if (std::find(ids.begin(), ids.end(), known) == ids.end()) ids.push_back(known);
    }
    if (ids.empty()) throw std::invalid_argument("--claims: no claim id given");
    std::vector<std::string> ordered;  // in ledger order
    for (const claim& c : book.claims) {
      if (std::find(ids.begin(), ids.end(), c.id) != ids.end()) ordered.push_back(c.id);
    }
    // Every claim of the scene (--claims all) is said so, not listed.
    const bool all_own = ordered.size() == s.claims.size() &&
                         std::all_of(s.claims.begin(), s.claims.end(), [&](const std::string& own) {
                           return std::find(ordered.begin(), ordered.end(), own) != ordered.end();
                         });
    s.claims = ordered;
    s.overrides["claims"] = ordered;
    parts.push_back(all_own ? "all " + std::to_string(ordered.size()) + " claims" : "claims " + joined(ordered) + " only");
  } else {
    s.claims.clear();
    s.overrides["claims"] = json::array();
    parts.push_back("no claims");
  }
  std::vector<std::string> sections;
  if (selection.sections) {
    for (const std::string& given : *selection.sections) {
      const std::string name = trimmed(given);
      if (name.empty() || name == "none") continue;
      if (find_section(book.sections, name) == nullptr) {
        throw std::invalid_argument("--sections: unknown section '" + name + "' (known: " + joined(section_names(book.sections)) + ", or none)");
      }
      if (std::find(sections.begin(), sections.end(), name) == sections.end()) sections.push_back(name);
    }
  }
  keep_sections(s, sections, book.sections);
  std::vector<std::string> ordered;
  for (const std::string& name : section_names(book.sections)) {
    if (std::find(sections.begin(), sections.end(), name) != sections.end()) ordered.push_back(name);
  }
  s.overrides["sections"] = ordered;
  parts.push_back(ordered.empty() ? "no sections" : "sections " + joined(ordered) + " only");
  s.selection = parts.front() + "; " + parts.back();
}

}  // namespace simpson::verify

namespace simpson::verify {

void apply_precisions(scene& s, const std::vector<std::string>& names) {
  std::vector<precision> parsed;
  std::vector<std::string> given;
  for (const std::string& name : names) {
    const std::string text = trimmed(name);
    if (text.empty()) continue;
    try {
      parsed.push_back(precision::parse(text));
    } catch (const std::invalid_argument& e) {
      throw std::invalid_argument(std::string("--precisions: ") + e.what());
    }
    given.push_back(text);
  }
  if (parsed.empty()) throw std::invalid_argument("--precisions: no precision given");
  experiment_settings& e = s.experiments;
  // Each section takes the list, ignores it, or refuses it (and says why): the registry's word.
  std::vector<std::string> applied{"claims"};
  for (const experiment_settings::entry& section : e.entries()) {
    if (section.section->precisions() == experiment_section::precisions_use::refused) {
      throw std::invalid_argument("--precisions: " + section.section->why_no_precisions(section.settings));
    }
    if (section.section->precisions() == experiment_section::precisions_use::applied) applied.push_back(section.section->name());
  }
  for (const precision& p : parsed) {
    if (p.exact() && applied.size() > 1) {
      throw std::invalid_argument("--precisions: '" + p.name() + "' has no cos or sin, and the sections " +
                                  joined(std::vector<std::string>(applied.begin() + 1, applied.end())) +
                                  " need floating precisions; drop it, or run the claims alone (--sections none)");
    }
  }
  s.precisions = parsed;
  for (experiment_settings::entry& section : e.entries()) {
    if (section.section->precisions() == experiment_section::precisions_use::applied) section.section->set_precisions(section.settings, parsed);
  }
  s.overrides["precisions"] = given;
  s.overrides["precisions_applied_to"] = applied;
}

}  // namespace simpson::verify
