// A scene's sections read and kept in the registry's order (experiment_section.hpp).

#include <simpson/verify/experiment_section.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace simpson::verify {

section_reader::section_reader(std::string origin, std::string section, const json& object, const std::set<std::string>& known)
    : origin_(std::move(origin)), section_(std::move(section)), object_(object) {
  if (!object.is_object()) throw scene_error("scene '" + origin_ + "': '" + section_ + "' must be an object");
  for (const auto& item : object.items()) {
    if (!known.count(item.key())) throw scene_error("scene '" + origin_ + "': unknown key '" + section_ + "." + item.key() + "'");
  }
}

void section_reader::fail(const std::string& why) const { throw scene_error("scene '" + origin_ + "': " + why); }

bool section_reader::flag(const std::string& key) const {
  const json& v = object_[key];
  if (!v.is_boolean()) fail(field(key) + " must be true or false, got " + v.dump());
  return v.get<bool>();
}

double section_reader::number(const std::string& key, double lo, double hi) const {
  const json& v = object_[key];
  if (!v.is_number() || !std::isfinite(v.get<double>()) || !(v.get<double>() > lo) || !(v.get<double>() <= hi)) {
    fail(field(key) + " must be a number greater than " + fmt::format("{:g}", lo) + " and at most " + fmt::format("{:g}", hi) + ", got " + v.dump());
  }
  return v.get<double>();
}

long long section_reader::integer(const json& v, const std::string& name, long long lo, long long hi) const {
  const bool integral = v.is_number_integer() || (v.is_number_float() && std::isfinite(v.get<double>()) &&
                                                  std::floor(v.get<double>()) == v.get<double>() && std::abs(v.get<double>()) < 9e18);
  if (!integral || v.get<double>() < static_cast<double>(lo) || v.get<double>() > static_cast<double>(hi)) {
    fail(name + " must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + v.dump());
  }
  return v.is_number_integer() ? v.get<long long>() : static_cast<long long>(v.get<double>());
}

long long section_reader::integer(const std::string& key, long long lo, long long hi) const { return integer(object_[key], field(key), lo, hi); }

std::vector<long long> section_reader::integers(const std::string& key, long long lo, long long hi) const {
  const json& v = object_[key];
  if (!v.is_array() || v.empty() || v.size() > 64) fail(field(key) + " must be a list of 1 to 64 integers");
  std::vector<long long> out;
  for (std::size_t k = 0; k < v.size(); ++k) out.push_back(integer(v[k], field(key) + "[" + std::to_string(k) + "]", lo, hi));
  return out;
}

std::vector<double> section_reader::numbers(const std::string& key, double lo, double hi) const {
  const json& v = object_[key];
  if (!v.is_array() || v.empty() || v.size() > 64) fail(field(key) + " must be a list of 1 to 64 numbers");
  std::vector<double> out;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const json& x = v[k];
    if (!x.is_number() || !std::isfinite(x.get<double>()) || !(x.get<double>() > lo) || !(x.get<double>() <= hi)) {
      fail(field(key) + "[" + std::to_string(k) + "] must be a number greater than " + fmt::format("{:g}", lo) + " and at most " +
           fmt::format("{:g}", hi) + ", got " + x.dump());
    }
    out.push_back(x.get<double>());
  }
  return out;
}

std::vector<precision> section_reader::precisions(const std::string& key) const {
  const json& v = object_[key];
  if (!v.is_array() || v.empty()) fail(field(key) + " must be a non-empty list of precision names");
  std::vector<precision> out;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string name = field(key) + "[" + std::to_string(k) + "]";
    if (!v[k].is_string()) fail(name + " must be a string");
    try {
      out.push_back(precision::parse(v[k].get<std::string>()));
    } catch (const std::invalid_argument& e) {
      fail(name + ": " + e.what());
    }
    if (out.back().exact()) fail(name + ": 'rational' has no cos or sin; experiments need a floating precision");
  }
  return out;
}

std::vector<std::string> section_reader::names(const std::string& key, const std::vector<std::string>& known) const {
  const json& v = object_[key];
  if (!v.is_array() || v.empty()) fail(field(key) + " must be a non-empty list of names");
  std::vector<std::string> out;
  std::string choices;
  for (const std::string& k : known) choices += (choices.empty() ? "" : ", ") + k;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string name = field(key) + "[" + std::to_string(k) + "]";
    if (!v[k].is_string()) fail(name + " must be a string");
    const std::string given = v[k].get<std::string>();
    if (std::find(known.begin(), known.end(), given) == known.end()) fail(name + ": unknown name '" + given + "' (known: " + choices + ")");
    if (std::find(out.begin(), out.end(), given) != out.end()) fail(name + ": '" + given + "' is listed twice");
    out.push_back(given);
  }
  return out;
}

std::vector<scheme_id> section_reader::schemes(const std::string& key) const {
  const json& v = object_[key];
  if (v.is_string() && v.get<std::string>() == "all") return all_schemes();
  if (!v.is_array() || v.empty()) fail(field(key) + " must be \"all\" or a non-empty list of scheme names");
  std::vector<scheme_id> out;
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string name = field(key) + "[" + std::to_string(k) + "]";
    if (!v[k].is_string()) fail(name + " must be a string");
    try {
      out.push_back(find_scheme(v[k].get<std::string>()).id);
    } catch (const std::invalid_argument& e) {
      fail(name + ": " + e.what());
    }
  }
  return out;
}

bool experiment_settings::has(const std::string& name) const {
  return std::any_of(entries_.begin(), entries_.end(), [&](const entry& e) { return e.section->name() == name; });
}

void experiment_settings::set(const experiment_section& section, std::any settings, const std::vector<const experiment_section*>& order) {
  for (entry& e : entries_) {
    if (e.section == &section) {
      e.settings = std::move(settings);
      return;
    }
  }
  entries_.push_back({&section, std::move(settings)});
  const auto rank = [&](const entry& e) { return std::find(order.begin(), order.end(), e.section) - order.begin(); };
  std::stable_sort(entries_.begin(), entries_.end(), [&](const entry& a, const entry& b) { return rank(a) < rank(b); });
}

void experiment_settings::remove(const std::string& name) {
  entries_.erase(std::remove_if(entries_.begin(), entries_.end(), [&](const entry& e) { return e.section->name() == name; }), entries_.end());
}

std::vector<std::string> experiment_settings::names() const {
  std::vector<std::string> out;
  for (const entry& e : entries_) out.push_back(e.section->name());
  return out;
}

const experiment_section* find_section(const std::vector<const experiment_section*>& registry, const std::string& name) {
  for (const experiment_section* s : registry) {
    if (s->name() == name) return s;
  }
  return nullptr;
}

experiment_settings parse_experiments(const json& doc, const std::string& origin, const std::vector<const experiment_section*>& registry) {
  // A section that takes precisions and does not name its own runs in the scene's floating ones.
  std::vector<precision> floating;
  if (doc.contains("precisions") && doc["precisions"].is_array()) {
    for (const json& p : doc["precisions"]) {
      try {
        if (p.is_string() && !precision::parse(p.get<std::string>()).exact()) floating.push_back(precision::parse(p.get<std::string>()));
      } catch (const std::invalid_argument&) {  // the scene's own parse names it
      }
    }
  }
  if (floating.empty()) floating.push_back(precision::parse("double"));
  experiment_settings e;
  for (const experiment_section* section : registry) {
    if (!doc.contains(section->name())) continue;
    const section_reader r(origin, section->name(), doc[section->name()], section->keys());
    e.set(*section, section->parse(r, floating), registry);
  }
  return e;
}

}  // namespace simpson::verify
