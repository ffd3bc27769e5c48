#include <simpson/verify/scene.hpp>

#include <simpson/verify/ledger.hpp>

#include "embedded_scenes.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>

namespace simpson::verify {
namespace {

[[noreturn]] void fail(const std::string& origin, const std::string& what) {
  throw std::invalid_argument("scene '" + origin + "': " + what);
}

/// Line and column (1-based) of a byte offset.
std::string position(const std::string& text, std::size_t offset) {
  std::size_t line = 1, column = 1;
  for (std::size_t k = 0; k < offset && k < text.size(); ++k) {
    if (text[k] == '\n') {
      ++line;
      column = 1;
    } else {
      ++column;
    }
  }
  return "line " + std::to_string(line) + ", column " + std::to_string(column);
}

/// A verdict a scene may expect: a judgment of the document (verdict.hpp's table says which).
verdict parse_verdict(const std::string& origin, const std::string& field, const std::string& v) {
  const std::optional<verdict> named = verdict_of_name(v);
  if (named && expectable(*named)) return *named;
  std::string judgments;
  for (const verdict_meaning& m : verdict_meanings) {
    if (m.expectable) judgments += (judgments.empty() ? "" : ", ") + std::string(m.name);
  }
  fail(origin, field + ": '" + v + "' is not a verdict a scene may expect (" + judgments + ")");
}

}  // namespace

scene parse_scene(const std::string& text, const std::string& origin, const claim_book& book) {
  nlohmann::json doc;
  try {
    doc = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    std::string what = e.what();
    const std::size_t cut = what.find("parse error");
    what = cut == std::string::npos ? what : what.substr(cut);
    fail(origin, "malformed JSON at " + position(text, e.byte == 0 ? 0 : e.byte - 1) + ": " + what);
  } catch (const nlohmann::json::exception& e) {
    // Not a syntax error but still unreadable, e.g. out_of_range 406 for a number that overflows
    // a double (found by the fuzzer): no position is known.
    std::string what = e.what();
    if (what.size() > 160) what = what.substr(0, 160) + "...";
    fail(origin, "malformed JSON: " + what);
  }
  if (!doc.is_object()) fail(origin, "the top level must be an object");
  // The scene's own keys, and a section's object under each section's name (the registry's).
  std::set<std::string> known{"name", "description", "claims", "precisions", "samples", "seed", "expected_overrides", "paper"};
  for (const experiment_section* section : book.sections) known.insert(section->name());
  for (const auto& item : doc.items()) {
    if (!known.count(item.key())) fail(origin, "unknown key '" + item.key() + "'");
  }
  scene s;
  s.source_text = text;
  if (!doc.contains("name") || !doc["name"].is_string()) fail(origin, "'name' must be a string");
  s.name = doc["name"].get<std::string>();
  if (s.name.empty() || s.name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_-") != std::string::npos) {
    fail(origin, "'name' must be non-empty lower-case letters, digits, '-' or '_', got '" + s.name + "'");
  }
  if (doc.contains("description")) {
    if (!doc["description"].is_string()) fail(origin, "'description' must be a string");
    s.description = doc["description"].get<std::string>();
  }
  s.experiments = parse_experiments(doc, origin, book.sections);
  if (!doc.contains("claims") && !s.experiments.any()) {
    fail(origin, "'claims' is missing (\"all\" or a list of ids; it may be left out only when an experiment section is present)");
  }
  const nlohmann::json claims = doc.contains("claims") ? doc["claims"] : nlohmann::json::array();
  std::set<std::string> wanted;
  if (claims.is_string() && (claims.get<std::string>() == "all" || claims.get<std::string>() == "beyond")) {
    // "all": every claim of the paper; "beyond": the ledger's part beyond the paper (section "beyond").
    const bool beyond = claims.get<std::string>() == "beyond";
    for (const claim& c : book.claims) {
      if ((c.section == "beyond") == beyond) wanted.insert(c.id);
    }
  } else if (claims.is_array() && (!claims.empty() || !doc.contains("claims"))) {
    for (std::size_t k = 0; k < claims.size(); ++k) {
      if (!claims[k].is_string()) fail(origin, "'claims[" + std::to_string(k) + "]' must be a string");
      try {
        wanted.insert(book.find(claims[k].get<std::string>()).id);
      } catch (const std::invalid_argument& e) {
        fail(origin, "'claims[" + std::to_string(k) + "]': " + e.what());
      }
    }
  } else {
    fail(origin, "'claims' must be \"all\" (the paper's), \"beyond\" (beyond the paper) or a non-empty list of claim ids");
  }
  for (const claim& c : book.claims) {
    if (wanted.count(c.id)) s.claims.push_back(c.id);
  }
  // The precisions of the claims' numeric rechecks: required with claims, "double" otherwise.
  const nlohmann::json precisions = doc.contains("precisions") || doc.contains("claims") ? doc.value("precisions", nlohmann::json())
                                                                                          : nlohmann::json::array({"double"});
  if (!precisions.is_array() || precisions.empty()) {
    fail(origin, "'precisions' must be a non-empty list of precision names");
  }
  for (std::size_t k = 0; k < precisions.size(); ++k) {
    const nlohmann::json& p = precisions[k];
    const std::string field = "'precisions[" + std::to_string(k) + "]'";
    if (!p.is_string()) fail(origin, field + " must be a string");
    try {
      s.precisions.push_back(precision::parse(p.get<std::string>()));
    } catch (const std::invalid_argument& e) {
      fail(origin, field + ": " + e.what());
    }
  }
  if (doc.contains("samples")) {
    const nlohmann::json& n = doc["samples"];
    if (!n.is_number_integer() || n.get<long long>() < 1 || n.get<long long>() > 10000) {
      fail(origin, "'samples' must be an integer from 1 to 10000, got " + n.dump());
    }
    s.samples = static_cast<unsigned>(n.get<long long>());
  }
  if (doc.contains("seed")) {
    const nlohmann::json& n = doc["seed"];
    if (!n.is_number_unsigned() && !(n.is_number_integer() && n.get<long long>() >= 0)) {
      fail(origin, "'seed' must be a non-negative integer, got " + n.dump());
    }
    s.seed = n.get<std::uint64_t>();
  }
  if (doc.contains("paper")) {
    if (!doc["paper"].is_string() || doc["paper"].get<std::string>().empty()) {
      fail(origin, "'paper' must be the path of the paper's LaTeX source, got " + doc["paper"].dump());
    }
    s.paper_file = doc["paper"].get<std::string>();
  }
  if (doc.contains("expected_overrides")) {
    const nlohmann::json& o = doc["expected_overrides"];
    if (!o.is_object()) fail(origin, "'expected_overrides' must be an object {claim id: verdict}");
    for (const auto& item : o.items()) {
      const std::string field = "'expected_overrides." + item.key() + "'";
      try {
        book.find(item.key());
      } catch (const std::invalid_argument& e) {
        fail(origin, field + ": " + e.what());
      }
      if (!item.value().is_string()) fail(origin, field + " must be a string");
      s.expected_overrides[item.key()] = parse_verdict(origin, field, item.value().get<std::string>());
    }
  }
  return s;
}

const std::map<std::string, std::string>& embedded_scenes() {
  static const std::map<std::string, std::string> scenes(std::begin(detail::embedded_scene_texts),
                                                         std::end(detail::embedded_scene_texts));
  return scenes;
}

scene load_scene(const std::string& name_or_path, const claim_book& book) {
  const auto embedded = embedded_scenes().find(name_or_path);
  if (embedded != embedded_scenes().end()) return parse_scene(embedded->second, name_or_path, book);
  std::ifstream in(name_or_path, std::ios::binary);
  if (!in) {
    throw std::invalid_argument("scene '" + name_or_path + "': no embedded scene of that name and no readable file");
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), name_or_path, book);
}

}  // namespace simpson::verify
