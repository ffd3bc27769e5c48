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

/// Reads the members of one experiment section, naming each field "section.key" in errors.
class section_reader {
 public:
  section_reader(const std::string& origin, const std::string& section, const nlohmann::json& object,
                 std::set<std::string> known)
      : origin_(origin), section_(section), object_(object) {
    if (!object.is_object()) fail(origin_, "'" + section_ + "' must be an object");
    for (const auto& item : object.items()) {
      if (!known.count(item.key())) fail(origin_, "unknown key '" + section_ + "." + item.key() + "'");
    }
  }
  bool has(const std::string& key) const { return object_.contains(key); }
  bool flag(const std::string& key) const {
    const nlohmann::json& v = object_[key];
    if (!v.is_boolean()) fail(origin_, field(key) + " must be true or false, got " + v.dump());
    return v.get<bool>();
  }
  /// A finite number with lo < v <= hi (JSON has no NaN or infinity; a number beyond double is
  /// refused by the parser).
  double number(const std::string& key, double lo, double hi) const {
    const nlohmann::json& v = object_[key];
    if (!v.is_number() || !std::isfinite(v.get<double>()) || !(v.get<double>() > lo) || !(v.get<double>() <= hi)) {
      fail(origin_, field(key) + " must be a number greater than " + fmt::format("{:g}", lo) + " and at most " +
                        fmt::format("{:g}", hi) + ", got " + v.dump());
    }
    return v.get<double>();
  }
  /// An integer lo <= v <= hi (a number like 1e7 is accepted when it is an integer).
  long long integer(const nlohmann::json& v, const std::string& name, long long lo, long long hi) const {
    const bool integral = v.is_number_integer() || (v.is_number_float() && std::isfinite(v.get<double>()) &&
                                                    std::floor(v.get<double>()) == v.get<double>() &&
                                                    std::abs(v.get<double>()) < 9e18);
    if (!integral || v.get<double>() < static_cast<double>(lo) || v.get<double>() > static_cast<double>(hi)) {
      fail(origin_, name + " must be an integer from " + std::to_string(lo) + " to " + std::to_string(hi) + ", got " + v.dump());
    }
    return v.is_number_integer() ? v.get<long long>() : static_cast<long long>(v.get<double>());
  }
  long long integer(const std::string& key, long long lo, long long hi) const { return integer(object_[key], field(key), lo, hi); }
  std::vector<long long> integers(const std::string& key, long long lo, long long hi) const {
    const nlohmann::json& v = object_[key];
    if (!v.is_array() || v.empty() || v.size() > 64) fail(origin_, field(key) + " must be a list of 1 to 64 integers");
    std::vector<long long> out;
    for (std::size_t k = 0; k < v.size(); ++k) out.push_back(integer(v[k], field(key) + "[" + std::to_string(k) + "]", lo, hi));
    return out;
  }
  std::vector<double> numbers(const std::string& key, double lo, double hi) const {
    const nlohmann::json& v = object_[key];
    if (!v.is_array() || v.empty() || v.size() > 64) fail(origin_, field(key) + " must be a list of 1 to 64 numbers");
    std::vector<double> out;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const nlohmann::json& x = v[k];
      if (!x.is_number() || !std::isfinite(x.get<double>()) || !(x.get<double>() > lo) || !(x.get<double>() <= hi)) {
        fail(origin_, field(key) + "[" + std::to_string(k) + "] must be a number greater than " + fmt::format("{:g}", lo) +
                          " and at most " + fmt::format("{:g}", hi) + ", got " + x.dump());
      }
      out.push_back(x.get<double>());
    }
    return out;
  }
  /// Floating precisions only: the experiments need cos, sin and a round-off to measure.
  std::vector<precision> precisions(const std::string& key) const {
    const nlohmann::json& v = object_[key];
    if (!v.is_array() || v.empty()) fail(origin_, field(key) + " must be a non-empty list of precision names");
    std::vector<precision> out;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const std::string name = field(key) + "[" + std::to_string(k) + "]";
      if (!v[k].is_string()) fail(origin_, name + " must be a string");
      try {
        out.push_back(precision::parse(v[k].get<std::string>()));
      } catch (const std::invalid_argument& e) {
        fail(origin_, name + ": " + e.what());
      }
      if (out.back().exact()) fail(origin_, name + ": 'rational' has no cos or sin; experiments need a floating precision");
    }
    return out;
  }
  /// A non-empty list of distinct names from `known`, in the order given.
  std::vector<std::string> names(const std::string& key, const std::vector<std::string>& known) const {
    const nlohmann::json& v = object_[key];
    if (!v.is_array() || v.empty()) fail(origin_, field(key) + " must be a non-empty list of names");
    std::vector<std::string> out;
    std::string choices;
    for (const std::string& k : known) choices += (choices.empty() ? "" : ", ") + k;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const std::string name = field(key) + "[" + std::to_string(k) + "]";
      if (!v[k].is_string()) fail(origin_, name + " must be a string");
      const std::string given = v[k].get<std::string>();
      if (std::find(known.begin(), known.end(), given) == known.end()) {
        fail(origin_, name + ": unknown name '" + given + "' (known: " + choices + ")");
      }
      if (std::find(out.begin(), out.end(), given) != out.end()) fail(origin_, name + ": '" + given + "' is listed twice");
      out.push_back(given);
    }
    return out;
  }
  std::vector<scheme_id> schemes(const std::string& key) const {
    const nlohmann::json& v = object_[key];
    if (v.is_string() && v.get<std::string>() == "all") return all_schemes();
    if (!v.is_array() || v.empty()) fail(origin_, field(key) + " must be \"all\" or a non-empty list of scheme names");
    std::vector<scheme_id> out;
    for (std::size_t k = 0; k < v.size(); ++k) {
      const std::string name = field(key) + "[" + std::to_string(k) + "]";
      if (!v[k].is_string()) fail(origin_, name + " must be a string");
      try {
        out.push_back(find_scheme(v[k].get<std::string>()).id);
      } catch (const std::invalid_argument& e) {
        fail(origin_, name + ": " + e.what());
      }
    }
    return out;
  }

 private:
  std::string field(const std::string& key) const { return "'" + section_ + "." + key + "'"; }
  std::string origin_, section_;
  const nlohmann::json& object_;
};

/// The most steps a single run may ask for (a larger N is refused as absurd, not merely costly).
constexpr long long max_steps = 1'000'000'000'000LL;

experiment_settings parse_experiments(const nlohmann::json& doc, const std::string& origin) {
  experiment_settings e;
  if (doc.contains("table1")) {
    const section_reader r(origin, "table1", doc["table1"], {"N", "figure_N", "m"});
    table1_settings t;
    if (r.has("N")) t.meshes = r.integers("N", 1, 1'000'000);
    if (r.has("figure_N")) t.figure_meshes = r.integer("figure_N", 1, 100'000);
    if (r.has("m")) t.m = r.number("m", 0, 1e300);
    e.table1 = t;
  }
  if (doc.contains("work_precision")) {
    const section_reader r(origin, "work_precision", doc["work_precision"],
                           {"schemes", "precisions", "N", "periods", "max_runs", "max_seconds", "benchmark", "forms"});
    work_precision_settings w;
    if (r.has("schemes")) w.schemes = r.schemes("schemes");
    if (!r.has("precisions")) fail(origin, "'work_precision.precisions' is missing");
    w.precisions = r.precisions("precisions");
    if (r.has("N")) w.meshes = r.integers("N", 1, max_steps);
    if (r.has("periods")) w.periods = r.integer("periods", 1, 1'000'000);
    for (const long long N : w.meshes) {
      if (static_cast<double>(N) * static_cast<double>(w.periods) > static_cast<double>(max_steps)) {
        fail(origin, "'work_precision': N x periods = " + std::to_string(N) + " x " + std::to_string(w.periods) +
                         " exceeds the limit of " + std::to_string(max_steps) + " steps per run");
      }
    }
    if (r.has("max_runs")) w.timing.max_runs = static_cast<unsigned>(r.integer("max_runs", 1, 1000));
    if (r.has("max_seconds")) w.timing.max_seconds = r.number("max_seconds", 0, 3600);
    if (r.has("benchmark")) w.benchmark = r.flag("benchmark");
    if (r.has("forms")) w.forms = r.names("forms", {"step", "matrix"});
    e.work_precision = w;
  }
  if (doc.contains("stability")) {
    const section_reader r(origin, "stability", doc["stability"],
                           {"precisions", "stiff_ratios", "stiff_doublings", "omega_h", "masses", "steps", "endpoint_power"});
    stability_settings st;
    if (!r.has("precisions")) fail(origin, "'stability.precisions' is missing");
    st.precisions = r.precisions("precisions");
    if (r.has("stiff_ratios")) st.stiff_ratios = r.numbers("stiff_ratios", 2, 1e8);
    if (r.has("stiff_doublings")) st.stiff_doublings = static_cast<int>(r.integer("stiff_doublings", 10, 60));
    if (r.has("omega_h")) st.omega_h = r.numbers("omega_h", 0, 1e3);
    if (r.has("masses")) st.masses = r.numbers("masses", 0, 1e300);
    if (r.has("steps")) st.steps = r.integer("steps", 1, max_steps);
    if (r.has("endpoint_power")) {
      // The smallest size whose fit decides every endpoint's growth (measured: from 5e5 every power
      // up to 1e12 decides; at 3e5 the growth just above 2√2 is not yet told from linear): a value
      // below it would make expectations fail that no run of that size can decide.
      constexpr long long deciding = 1000000;
      st.endpoint_power = r.integer("endpoint_power", 1, 1000000000000LL);
      if (st.endpoint_power < deciding) {
        fail(origin, fmt::format("'stability.endpoint_power' must be at least {}, the smallest size whose fit decides the endpoints' "
                                 "growth (bounded, linear or exponential; docs/stiff.md), got {}",
                                 deciding, st.endpoint_power));
      }
    }
    e.stability = st;
  }
  if (doc.contains("long_time")) {
    const section_reader r(origin, "long_time", doc["long_time"],
                           {"steps_double", "steps_mpfr", "mpfr_digits", "omega_h", "windows"});
    long_time_settings l;
    if (r.has("steps_double")) l.steps_double = r.integer("steps_double", 1, max_steps);
    if (r.has("steps_mpfr")) l.steps_mpfr = r.integer("steps_mpfr", 1, max_steps);
    if (r.has("mpfr_digits")) {
      l.mpfr_digits = static_cast<unsigned>(r.integer("mpfr_digits", precision::min_mpfr_digits, precision::max_mpfr_digits));
    }
    if (r.has("omega_h")) l.omega_h = r.number("omega_h", 0, 2);
    if (r.has("windows")) l.windows = r.integer("windows", 1, 100'000);
    e.long_time = l;
  }
  if (doc.contains("fpu")) {
    const section_reader r(origin, "fpu", doc["fpu"],
                           {"m", "omega", "omega_h", "end_time", "scan_from", "scan_to", "scan_step", "scan_end_time", "samples",
                            "exchange_time", "reference_omega_h", "resonances", "equal_cost_omega_h"});
    fpu_settings f;
    if (r.has("m")) f.m = static_cast<int>(r.integer("m", 1, 20));
    if (r.has("omega")) f.omega = r.number("omega", 1, 1e4);
    if (r.has("omega_h")) f.omega_h = r.numbers("omega_h", 0, 10);
    if (r.has("end_time")) f.end_time = r.number("end_time", 0, 1e6);
    if (r.has("scan_from")) f.scan_from = r.number("scan_from", 0, 10);
    if (r.has("scan_to")) f.scan_to = r.number("scan_to", 0, 10);
    if (r.has("scan_step")) f.scan_step = r.number("scan_step", 0, 10);
    if (r.has("scan_end_time")) f.scan_end_time = r.number("scan_end_time", 0, 1e5);
    if (r.has("samples")) f.samples = static_cast<int>(r.integer("samples", 10, 100000));
    if (r.has("exchange_time")) f.exchange_time = r.number("exchange_time", 0, 1e6);
    if (r.has("reference_omega_h")) f.reference_omega_h = r.number("reference_omega_h", 0.001, 10);
    if (r.has("equal_cost_omega_h")) f.equal_cost_omega_h = r.numbers("equal_cost_omega_h", 0.001, 10);
    if (r.has("resonances")) {  // θ = 2π/k: k = 2 is θ = π, a band end, where every run is at the edge of stability
      const std::vector<long long> k = r.integers("resonances", 3, 12);
      f.resonances.assign(k.begin(), k.end());
    }
    if (f.scan_to < f.scan_from) fail(origin, "'fpu.scan_to' must be at least 'fpu.scan_from'");
    if ((f.scan_to - f.scan_from) / f.scan_step > 1000) fail(origin, "'fpu.scan_step' gives more than 1000 points from 'fpu.scan_from' to 'fpu.scan_to'");
    e.fpu = f;
  }
  if (doc.contains("nonlinear")) {
    const section_reader r(origin, "nonlinear", doc["nonlinear"],
                           {"parts", "pendulum_q0", "pendulum_T", "pendulum_N", "mpfr_digits", "energy_steps", "brouwer_h", "brouwer_steps", "problems", "N",
                            "eccentricity", "kepler_periods", "reference_digits", "fpu_T", "max_runs", "max_seconds", "double_pendulum_N"});
    nonlinear_settings n;
    // q0 = π is the unstable equilibrium, where the exact solution (k = 1) has no period.
    if (r.has("pendulum_q0")) n.pendulum_q0 = r.number("pendulum_q0", 0, 3.14159);
    if (r.has("pendulum_T")) n.pendulum_T = r.number("pendulum_T", 0, 1e6);
    if (r.has("pendulum_N")) n.pendulum_N = r.integers("pendulum_N", 1, 100'000'000);
    if (r.has("mpfr_digits")) {
      n.mpfr_digits = static_cast<unsigned>(r.integer("mpfr_digits", precision::min_mpfr_digits, precision::max_mpfr_digits));
    }
    if (r.has("energy_steps")) n.energy_steps = r.integer("energy_steps", 1, max_steps);
    // Up to h = 1 the Newton start q + hp/2 converges for the pendulum's |p| ≤ 2.
    if (r.has("brouwer_h")) n.brouwer_h = r.number("brouwer_h", 0, 1);
    if (r.has("brouwer_steps")) n.brouwer_steps = r.integer("brouwer_steps", 1, max_steps);
    if (r.has("parts")) n.parts = r.names("parts", nonlinear_part_names());
    if (r.has("problems")) n.problems = r.names("problems", nonlinear_problem_names());
    if (r.has("kepler_periods")) n.kepler_periods = static_cast<int>(r.integer("kepler_periods", 1, 1000));
    if (r.has("N")) n.N = r.integers("N", 1, 100'000'000);
    if (r.has("eccentricity")) {
      // 0 <= e < 1 is an ellipse; e near 1 needs steps far below the perihelion distance 1 − e.
      n.eccentricity = r.number("eccentricity", -1e-300, 0.95);
    }
    if (r.has("reference_digits")) {
      n.reference_digits = static_cast<unsigned>(r.integer("reference_digits", 20, precision::max_mpfr_digits));
    }
    if (r.has("fpu_T")) n.fpu_T = r.number("fpu_T", 0, 1e4);
    if (r.has("max_runs")) n.timing.max_runs = static_cast<unsigned>(r.integer("max_runs", 1, 1000));
    if (r.has("max_seconds")) n.timing.max_seconds = r.number("max_seconds", 0, 3600);
    if (r.has("double_pendulum_N")) n.double_pendulum_N = r.integers("double_pendulum_N", 1, 100'000'000);
    e.nonlinear = n;
  }
  if (doc.contains("floating")) {
    const section_reader r(origin, "floating", doc["floating"], {"steppers", "formats", "h_denominator", "samples"});
    floating_settings f;
    if (r.has("steppers")) f.steppers = r.names("steppers", floating_stepper_names());
    if (r.has("formats")) f.formats = r.names("formats", {"float32", "double"});
    if (r.has("h_denominator")) f.h_denominator = r.integer("h_denominator", 1, 1'000'000);
    if (r.has("samples")) f.samples = static_cast<int>(r.integer("samples", 1, 10'000'000));
    e.floating = f;
  }
  if (doc.contains("family")) {
    const section_reader r(origin, "family", doc["family"], {"max_degree", "budget_seconds", "ginac", "node_check_degree"});
    family_settings f;
    if (r.has("max_degree")) f.max_degree = static_cast<int>(r.integer("max_degree", 1, 8));
    if (r.has("budget_seconds")) f.budget_seconds = r.number("budget_seconds", 0, 3600);
    if (r.has("ginac")) f.ginac = r.flag("ginac");
    if (r.has("node_check_degree")) f.node_check_degree = static_cast<int>(r.integer("node_check_degree", 0, 4));
    e.family = f;
  }
  return e;
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
  static const std::set<std::string> known{"name", "description", "claims", "precisions", "samples", "seed", "expected_overrides",
                                         "paper", "table1", "work_precision", "stability", "long_time",
                                         "nonlinear", "floating", "family", "fpu"};
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
  s.experiments = parse_experiments(doc, origin);
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
