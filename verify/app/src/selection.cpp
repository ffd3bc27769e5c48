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

void keep_sections(scene& s, const std::vector<std::string>& names) {
  experiment_settings& e = s.experiments;
  const auto wanted = [&names](const char* name) { return std::find(names.begin(), names.end(), name) != names.end(); };
  if (!wanted("table1")) e.table1.reset();
  else if (!e.table1) e.table1 = table1_settings{};
  if (!wanted("work_precision")) {
    e.work_precision.reset();
  } else if (!e.work_precision) {
    e.work_precision = work_precision_settings{};
    e.work_precision->precisions = floating_precisions(s);
  }
  if (!wanted("stability")) {
    e.stability.reset();
  } else if (!e.stability) {
    e.stability = stability_settings{};
    e.stability->precisions = floating_precisions(s);
  }
  if (!wanted("long_time")) e.long_time.reset();
  else if (!e.long_time) e.long_time = long_time_settings{};
  if (!wanted("nonlinear")) e.nonlinear.reset();
  else if (!e.nonlinear) e.nonlinear = nonlinear_settings{};
  if (!wanted("floating")) e.floating.reset();
  else if (!e.floating) e.floating = floating_settings{};
  if (!wanted("family")) e.family.reset();
  else if (!e.family) e.family = family_settings{};
  if (!wanted("fpu")) e.fpu.reset();
  else if (!e.fpu) e.fpu = fpu_settings{};
}

}  // namespace

const std::vector<std::string>& section_names() {
  static const std::vector<std::string> names{"table1", "work_precision", "stability", "long_time", "nonlinear", "floating", "family", "fpu"};
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
      if (std::find(section_names().begin(), section_names().end(), name) == section_names().end()) {
        throw std::invalid_argument("--sections: unknown section '" + name + "' (known: " + joined(section_names()) + ", or none)");
      }
      if (std::find(sections.begin(), sections.end(), name) == sections.end()) sections.push_back(name);
    }
  }
  keep_sections(s, sections);
  std::vector<std::string> ordered;
  for (const std::string& name : section_names()) {
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
  if (e.long_time) {
    throw std::invalid_argument("--precisions: the long_time section compares double with mpfr:" +
                                std::to_string(e.long_time->mpfr_digits) +
                                " by design and takes no precision list; leave it out with --sections, or set "
                                "long_time.mpfr_digits in a scene file");
  }
  if (e.nonlinear) {
    throw std::invalid_argument("--precisions: the nonlinear section runs in mpfr:" + std::to_string(e.nonlinear->mpfr_digits) +
                                " and double by design and takes no precision list; leave it out with --sections, or set "
                                "nonlinear.mpfr_digits in a scene file");
  }
  std::vector<std::string> applied{"claims"};
  if (e.work_precision) applied.push_back("work_precision");
  if (e.stability) applied.push_back("stability");
  for (const precision& p : parsed) {
    if (p.exact() && applied.size() > 1) {
      throw std::invalid_argument("--precisions: '" + p.name() + "' has no cos or sin, and the sections " +
                                  joined(std::vector<std::string>(applied.begin() + 1, applied.end())) +
                                  " need floating precisions; drop it, or run the claims alone (--sections none)");
    }
  }
  s.precisions = parsed;
  if (e.work_precision) e.work_precision->precisions = parsed;
  if (e.stability) e.stability->precisions = parsed;
  s.overrides["precisions"] = given;
  s.overrides["precisions_applied_to"] = applied;
}

}  // namespace simpson::verify
