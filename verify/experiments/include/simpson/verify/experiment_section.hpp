#pragma once
// An experiment section as one registry entry (LLVM lit's test format: one object the runner
// iterates): its name, how a scene's object configures it, what it costs, how it runs, and the
// run-wide options it takes. The app names no section: it iterates the registry the book gives
// (ledger.hpp, experiment_sections()). Adding a section is its own files (its settings, its run, its
// typed_section) and one line of that registry.

#include <simpson/precision.hpp>
#include <simpson/verify/json.hpp>
#include <simpson/verify/progress.hpp>
#include <simpson/verify/result_model.hpp>
#include <simpson/scheme.hpp>

#include <any>
#include <memory>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <typeinfo>
#include <vector>

namespace simpson::verify {

class run_memo;       // run_memo.hpp
struct paper_reading;  // paper_reading.hpp: the run's document, for a section that reads it

/// A scene that does not read: "scene 'ORIGIN': why" (bad input, exit 2).
class scene_error : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

/// Reads one section's object of a scene file, naming each field "section.key" in its errors.
class section_reader {
 public:
  /// Throws scene_error when `object` is not an object or has a key not in `known`.
  section_reader(std::string origin, std::string section, const json& object, const std::set<std::string>& known);
  bool has(const std::string& key) const { return object_.contains(key); }
  bool flag(const std::string& key) const;
  /// A finite number with lo < v <= hi.
  double number(const std::string& key, double lo, double hi) const;
  /// An integer lo <= v <= hi (1e7 accepted when it is an integer).
  long long integer(const std::string& key, long long lo, long long hi) const;
  std::vector<long long> integers(const std::string& key, long long lo, long long hi) const;
  std::vector<double> numbers(const std::string& key, double lo, double hi) const;
  /// Floating precisions only: the experiments need cos, sin and a round-off to measure.
  std::vector<precision> precisions(const std::string& key) const;
  /// A non-empty list of distinct names from `known`, in the order given.
  std::vector<std::string> names(const std::string& key, const std::vector<std::string>& known) const;
  std::vector<scheme_id> schemes(const std::string& key) const;
  /// Throws scene_error: "scene 'ORIGIN': 'section.key' why", or the section's own words.
  [[noreturn]] void fail(const std::string& why) const;
  std::string field(const std::string& key) const { return "'" + section_ + "." + key + "'"; }

 private:
  long long integer(const json& v, const std::string& name, long long lo, long long hi) const;
  std::string origin_, section_;
  const json& object_;
};

/// The most steps a single run may ask for (a larger N is refused as absurd, not merely costly).
inline constexpr long long max_steps = 1'000'000'000'000LL;

/// What the command line sets for every section that takes it.
struct section_options {
  std::optional<unsigned> timing_runs;  // --timing-runs: timed runs per configuration
  bool timed = true;                    // --no-timing: measure no run time
  bool long_run = false;                // --long
  bool certify = false;                 // --certify: check the section's Coq proofs with coqc
};

/// What a run gives a section: the run's memo, where it reports its work, the run's document.
struct section_inputs {
  run_memo* memo = nullptr;
  progress_sink progress;
  const paper_reading* paper = nullptr;
};

/// A section's estimated cost in double-step units (experiment_cost.hpp) and its line.
struct section_cost {
  double units = 0;
  std::string line;
};

/// One kind of experiment section. Its settings travel type-erased (std::any) between the scene
/// and the run; typed_section<Settings> below does the casts, so that a section is written typed.
class experiment_section {
 public:
  virtual ~experiment_section() = default;
  virtual const std::string& name() const = 0;
  /// One line for --sections' help and the docs.
  virtual const std::string& summary() const = 0;
  /// Its settings from the scene's object under its name; `floating` is the scene's floating
  /// precisions (double when it has none), the default of a section that takes precisions.
  virtual std::any parse(const section_reader& r, const std::vector<precision>& floating) const = 0;
  /// The keys its object may hold.
  virtual std::set<std::string> keys() const = 0;
  /// Its settings when --sections asks for it and the scene has no object for it.
  virtual std::any defaults(const std::vector<precision>& floating) const = 0;
  virtual section_cost cost(const std::any& settings) const = 0;
  virtual section_result run(const std::any& settings, const section_inputs& inputs) const = 0;
  /// --precisions: how the section takes a precision list.
  enum class precisions_use { ignored, applied, refused };
  virtual precisions_use precisions() const { return precisions_use::ignored; }
  virtual void set_precisions(std::any&, const std::vector<precision>&) const {}
  /// Why it refuses a precision list (precisions() == refused).
  virtual std::string why_no_precisions(const std::any&) const { return {}; }
  /// Whether it times runs (--timing-runs applies to it).
  virtual bool times_runs() const { return false; }
  /// Whether --long asks for it (added when the scene has none) and lengthens its runs.
  virtual bool runs_long() const { return false; }
  /// The run-wide options, applied to its settings.
  virtual void apply(std::any&, const section_options&) const {}
  /// The type of its settings: experiment_settings finds a section by it.
  virtual const std::type_info& settings_type() const = 0;
};

/// A section written on its settings type: the casts are done here, once.
template <class Settings>
class typed_section : public experiment_section {
 public:
  typed_section(std::string name, std::string summary) : name_(std::move(name)), summary_(std::move(summary)) {}
  const std::string& name() const final { return name_; }
  const std::string& summary() const final { return summary_; }
  std::any parse(const section_reader& r, const std::vector<precision>& floating) const final { return read(r, floating); }
  std::any defaults(const std::vector<precision>& floating) const final { return initial(floating); }
  section_cost cost(const std::any& s) const final { return estimate(std::any_cast<const Settings&>(s)); }
  section_result run(const std::any& s, const section_inputs& inputs) const final { return compute(std::any_cast<const Settings&>(s), inputs); }
  void set_precisions(std::any& s, const std::vector<precision>& p) const final { with_precisions(std::any_cast<Settings&>(s), p); }
  std::string why_no_precisions(const std::any& s) const final { return refusal(std::any_cast<const Settings&>(s)); }
  void apply(std::any& s, const section_options& o) const final { with_options(std::any_cast<Settings&>(s), o); }
  const std::type_info& settings_type() const final { return typeid(Settings); }

 protected:
  virtual Settings read(const section_reader& r, const std::vector<precision>& floating) const = 0;
  virtual Settings initial(const std::vector<precision>& floating) const = 0;
  virtual section_cost estimate(const Settings& s) const = 0;
  virtual section_result compute(const Settings& s, const section_inputs& inputs) const = 0;
  virtual void with_precisions(Settings&, const std::vector<precision>&) const {}
  virtual std::string refusal(const Settings&) const { return {}; }
  virtual void with_options(Settings&, const section_options&) const {}

 private:
  std::string name_, summary_;
};

/// The sections a scene asks for, in the registry's order, each with its settings.
class experiment_settings {
 public:
  struct entry {
    const experiment_section* section = nullptr;
    std::any settings;
  };
  bool any() const { return !entries_.empty(); }
  const std::vector<entry>& entries() const { return entries_; }
  std::vector<entry>& entries() { return entries_; }
  bool has(const std::string& name) const;
  /// Adds a section, kept in `order` (the registry's); replaces its settings when present.
  void set(const experiment_section& section, std::any settings, const std::vector<const experiment_section*>& order);
  void remove(const std::string& name);
  /// The settings of the section whose settings are of type Settings, or null.
  template <class Settings>
  Settings* find() {
    for (entry& e : entries_) {
      if (e.section->settings_type() == typeid(Settings)) return &std::any_cast<Settings&>(e.settings);
    }
    return nullptr;
  }
  template <class Settings>
  const Settings* find() const {
    for (const entry& e : entries_) {
      if (e.section->settings_type() == typeid(Settings)) return &std::any_cast<const Settings&>(e.settings);
    }
    return nullptr;
  }
  /// The section names, in order.
  std::vector<std::string> names() const;

 private:
  std::vector<entry> entries_;
};

/// The scene's sections from its top-level object: each registry section whose name is a key.
experiment_settings parse_experiments(const json& doc, const std::string& origin, const std::vector<const experiment_section*>& registry);

/// A section of `registry` by name; null when none.
const experiment_section* find_section(const std::vector<const experiment_section*>& registry, const std::string& name);

}  // namespace simpson::verify
