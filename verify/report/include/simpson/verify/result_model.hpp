#pragma once
// What an experiment section returns: typed tables and plots described as data, with prose between
// them. One writer (section_render.hpp) renders JSON, Markdown, CSV, the gnuplot data and scripts
// from it; a section computes numbers and describes them, and never formats a file itself.

#include <simpson/verify/json.hpp>
#include <simpson/verify/figure.hpp>

#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

namespace simpson::verify {

/// A column of a table. `key` names it in JSON and CSV, `header` (with `unit`) in Markdown;
/// numbers are shown to `digits` significant digits in Markdown, or with `digits` decimals when
/// `fixed` (counts of digits, percentages), or with digits = 0 as given (a double input, such as a
/// scene's ωh, in its shortest round-trip decimal); JSON and CSV keep every digit.
struct column {
  column(std::string key_, std::string header_, std::string unit_ = {}, int digits_ = 3)
      : key(std::move(key_)), header(std::move(header_)), unit(std::move(unit_)), digits(digits_) {}
  /// A column shown in fixed notation with `decimals` decimals.
  static column fixed_point(std::string key_, std::string header_, int decimals) {
    column c(std::move(key_), std::move(header_), {}, decimals);
    c.fixed = true;
    return c;
  }
  std::string key;
  std::string header;
  std::string unit;
  int digits = 3;
  bool fixed = false;
};

using table_row = std::vector<figure>;

/// Where a table is rendered: report.json and report.md always; a CSV file when `csv_file` is set.
/// `markdown = false` keeps a long-format table out of report.md (a wide table shows it there).
/// A `timing` table holds run times: it goes into timing.json and timing.md instead, so that every
/// other file of a report is the same from run to run (section_render.hpp).
struct table {
  table(std::string key_, std::string title_, std::string intro_, std::vector<column> columns_)
      : key(std::move(key_)), title(std::move(title_)), intro(std::move(intro_)), columns(std::move(columns_)) {}
  std::string key;    // member of the section in report.json ("rows", "stiff", ...)
  std::string title;  // "### title" in report.md; empty for none
  std::string intro;  // Markdown before the table: the conventions a reader needs
  std::vector<column> columns;
  std::vector<table_row> rows;
  std::string csv_file;
  bool markdown = true;
  bool json = true;
  bool timing = false;

  /// Appends a row; throws std::logic_error when its size differs from the columns'.
  void add(table_row row);
};

enum class line_style { lines, points, lines_points, dashed };

/// One curve: its points (figures as computed; points outside double's range are not drawn, and the
/// plot's caption says how many), a title, and a style. `color` indexes a fixed palette, so that one
/// scheme keeps its colour across panels; `point` is a gnuplot point type.
struct series {
  explicit series(std::string title_, line_style style_ = line_style::lines_points, int color_ = 0, int point_ = 7,
                  int dash_ = 1)
      : title(std::move(title_)), style(style_), color(color_), point(point_), dash(dash_) {}
  std::string title;
  std::vector<figure> x, y;
  line_style style = line_style::lines_points;
  int color = 0;
  int point = 7;
  int dash = 1;  // gnuplot dash type of a line: 1 solid, 2 dashed, 3 short dashes, 4 dash-dot, 5 dash-dot-dot
  /// A guide (a slope, a round-off floor): drawn, but the y range is fitted to the data alone.
  bool reference = false;
  void add(figure xv, figure yv) {
    x.push_back(std::move(xv));
    y.push_back(std::move(yv));
  }
};

/// A guide y = y₀ (x₀/x)^order through (x₀, y₀) over the given x (a convergence slope): dashed, a
/// reference (so the y range is fitted to the data alone). Anchor it a factor below the curve it
/// compares with, so that it runs beside the curve instead of on it.
inline series slope_guide(std::string title, int color, double x0, double y0, const std::vector<long long>& xs, int order) {
  series guide(std::move(title), line_style::dashed, color);
  guide.reference = true;
  for (const long long x : xs) guide.add(figure::integer(x), figure::of(y0 * std::pow(x0 / static_cast<double>(x), order)));
  return guide;
}

struct axis {
  axis(std::string label_ = {}, bool log_ = false) : label(std::move(label_)), log(log_) {}
  std::string label;
  bool log = false;
  /// A fixed range (a digits axis runs from 0 to its precision's digits); unset: fitted to the data.
  std::optional<std::pair<double, double>> range;
  /// Labelled tics (the rows of a chart); empty: gnuplot's own.
  std::vector<std::pair<double, std::string>> tics;
};

struct panel {
  panel(std::string title_, axis x_, axis y_, std::vector<series> curves_ = {}, std::string key_ = "top right")
      : title(std::move(title_)), x(std::move(x_)), y(std::move(y_)), curves(std::move(curves_)), key(std::move(key_)) {}
  std::string title;
  axis x, y;
  std::vector<series> curves;
  std::string key = "top right";  // gnuplot legend position of a single-panel plot
};

/// A plot of one or more panels. With several panels, their curves share one legend in a column to
/// the right of the panels (each title once), so that no legend covers a curve.
struct plot_description {
  plot_description(std::string name_, std::string caption_, std::vector<panel> panels_, int columns_ = 1, int width_ = 800,
                   int height_ = 500)
      : name(std::move(name_)), caption(std::move(caption_)), panels(std::move(panels_)), columns(columns_), width(width_),
        height(height_) {}
  std::string name;     // files <name>.dat, <name>.gp, <name>.svg, <name>.png
  std::string caption;
  std::vector<panel> panels;
  int columns = 1;      // panels per row
  int width = 800;      // pixels
  int height = 500;
  bool timing = false;  // a plot of run times: shown in timing.md, not report.md
};

struct prose {
  std::string markdown;
};

using section_block = std::variant<prose, table, plot_description>;

/// What a section's run is expected to show, against what it showed: a prediction made without
/// the run (an exact analysis, a proved law) beside the figure the run measured. A section records
/// each one it decides; one that fails fails the run (exit 1) and its JUnit testcase, as a claim
/// whose verdict is not the expected one does, so that a changed result is not only a `compare` line.
struct expectation {
  std::string key;        // unique within its section: the JUnit testcase's name
  std::string statement;  // what is expected, in words
  std::string predicted;  // the prediction, and what it rests on
  std::string observed;   // what the run measured
  bool holds = false;
};

/// An experiment section as data.
struct section_result {
  std::string name;   // scene key: "table1", "work_precision", "stability", "long_time"
  std::string title;  // "## title" in report.md
  json conventions = json::object();  // the settings the numbers depend on, as the scene gave them
  json timing_conventions = json::object();  // how its run times were measured (timing.json)
  std::vector<section_block> blocks;
  std::vector<expectation> expectations;

  section_result& text(std::string markdown) {
    blocks.emplace_back(prose{std::move(markdown)});
    return *this;
  }
  section_result& add(table t) {
    blocks.emplace_back(std::move(t));
    return *this;
  }
  section_result& add(plot_description p) {
    blocks.emplace_back(std::move(p));
    return *this;
  }
  section_result& expect(expectation e) {
    expectations.push_back(std::move(e));
    return *this;
  }
  const table* find_table(const std::string& key) const;
};

}  // namespace simpson::verify
