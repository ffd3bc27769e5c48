#include <simpson/verify/section_render.hpp>

#include <simpson/verify/markdown_text.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace simpson::verify {

json figure_json(const figure& f) {
  switch (f.what()) {
    case figure::kind::empty: return "";
    case figure::kind::number:
      if (f.as_computed_double()) return *f.as_computed_double();
      return f.full_text();
    case figure::kind::integer: return std::stoll(f.value());
    case figure::kind::flag: return f.value() == "yes";
    case figure::kind::exact:
    case figure::kind::text:
    case figure::kind::fault: return f.value();
  }
  return f.value();
}

std::string markdown_cell(const std::string& text) { return markdown_escaped(text); }

namespace {

/// A CSV field, quoted when it holds a comma, a quote or a newline.
std::string csv_field(const std::string& text) {
  if (text.find_first_of(",\"\n") == std::string::npos) return text;
  std::string out = "\"";
  for (const char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

json table_json(const table& t) {
  json rows = json::array();
  for (const table_row& row : t.rows) {
    json r = json::object();
    for (std::size_t k = 0; k < t.columns.size(); ++k) {
      if (row[k].what() != figure::kind::empty) r[t.columns[k].key] = figure_json(row[k]);
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

std::string table_markdown(const table& t) {
  std::string md;
  if (!t.title.empty()) md += "### " + t.title + "\n\n";
  if (!t.intro.empty()) md += t.intro + "\n\n";
  md += "|";
  for (const column& c : t.columns) md += " " + markdown_cell(c.unit.empty() ? c.header : c.header + " (" + c.unit + ")") + " |";
  md += "\n|";
  for (std::size_t k = 0; k < t.columns.size(); ++k) md += "---|";
  md += "\n";
  for (const table_row& row : t.rows) {
    md += "|";
    for (std::size_t k = 0; k < t.columns.size(); ++k) md += " " + markdown_cell(display(row[k], t.columns[k].digits, t.columns[k].fixed)) + " |";
    md += "\n";
  }
  return md + "\n";
}

std::string table_csv(const table& t) {
  std::string csv;
  for (std::size_t k = 0; k < t.columns.size(); ++k) csv += (k ? "," : "") + csv_field(t.columns[k].key);
  csv += "\n";
  for (const table_row& row : t.rows) {
    for (std::size_t k = 0; k < t.columns.size(); ++k) csv += (k ? "," : "") + csv_field(row[k].full_text());
    csv += "\n";
  }
  return csv;
}

/// True when a log-y panel has values beyond double's range: it is then drawn as log10 of its
/// values on a linear axis (computed from each figure's decimal text), so that every point shows.
bool drawn_as_log10(const panel& pan) {
  if (!pan.y.log) return false;
  for (const series& s : pan.curves) {
    for (const figure& y : s.y) {
      if (y.is_number() && !y.plottable() && y.log10_magnitude()) return true;
    }
  }
  return false;
}

/// The points of a curve gnuplot can draw: both coordinates within double's range (or, on a panel
/// drawn as log10, y as its log10), and positive on a log axis. Faults are left out (the tables
/// have them).
std::vector<std::pair<double, double>> drawable_points(const panel& pan, const series& s) {
  const bool log10_y = drawn_as_log10(pan);
  std::vector<std::pair<double, double>> points;
  for (std::size_t k = 0; k < s.x.size(); ++k) {
    const auto x = s.x[k].plottable();
    const auto y = log10_y ? s.y[k].log10_magnitude() : s.y[k].plottable();
    if (!x || !y || (pan.x.log && !(*x > 0)) || (!log10_y && pan.y.log && !(*y > 0))) continue;
    points.emplace_back(*x, *y);
  }
  return points;
}

/// The data file of a plot: one block (gnuplot's `index`) per curve with drawable points, in panel
/// order; plot_commands numbers the blocks the same way.
std::string plot_data(const plot_description& p) {
  std::string data = "# " + p.caption + "\n# one block per curve: x y\n";
  for (const panel& pan : p.panels) {
    for (const series& s : pan.curves) {
      const auto points = drawable_points(pan, s);
      if (points.empty()) continue;
      data += "# " + pan.title + ": " + s.title + "\n";
      for (const auto& [x, y] : points) data += fmt::format("{:.9g} {:.9g}\n", x, y);
      data += "\n\n";
    }
  }
  return data;
}

/// Gnuplot's quoting of a title: single quotes doubled.
std::string gp_quote(const std::string& text) {
  std::string out = "'";
  for (const char c : text) out += c == '\'' ? std::string("''") : std::string(1, c);
  return out + "'";
}

// A fixed palette, so that curve k has the same colour in every panel and every plot.
constexpr const char* palette[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e",
                                   "#8c564b", "#e377c2", "#17becf", "#7f7f7f", "#000000"};

/// The width in pixels of the legend column of a plot with several panels.
constexpr int legend_width = 380;  // room for 24 characters at the 12-point-or-more text of report_directory.cpp

/// The gnuplot `with` clause of a curve: its style, colour, point type and dash type.
std::string curve_style(const series& s) {
  const char* color = palette[static_cast<std::size_t>(s.color) % std::size(palette)];
  switch (s.style) {
    case line_style::lines: return fmt::format("w l lw 2 dt {} lc rgb '{}'", s.dash, color);
    case line_style::points: return fmt::format("w p pt {} ps 1.6 lc rgb '{}'", s.point, color);
    case line_style::lines_points: return fmt::format("w lp pt {} ps 0.8 lw 1.2 dt {} lc rgb '{}'", s.point, s.dash, color);
    // A guide: dashed (dash type 2) unless it asks for another, so that two guides of one panel differ.
    case line_style::dashed: return fmt::format("w l lw 1.5 dt {} lc rgb '{}'", s.dash == 1 ? 2 : s.dash, color);
  }
  return "w l";
}

/// Range commands for one axis: fixed when the axis has a range; otherwise fitted to the points
/// given (the data curves, without guides), with a margin, and on a log axis spanning many decades,
/// major tics every few decades and no minor tics, so that labels never crowd.
std::string axis_range(const char* name, const axis& a, bool log, const std::vector<double>& values) {
  if (a.range) return fmt::format("set {}range [{:.6g}:{:.6g}]\n", name, a.range->first, a.range->second);
  if (values.empty()) return fmt::format("set autoscale {}\n", name);
  const double low = *std::min_element(values.begin(), values.end()), high = *std::max_element(values.begin(), values.end());
  std::string gp;
  if (log) {
    const double decades = std::log10(high / low);
    const double margin = std::pow(10.0, std::max(0.04, 0.05 * decades));  // 5% of the span on each side
    gp += fmt::format("set {}range [{:.6g}:{:.6g}]\n", name, low / margin, high * margin);
    std::vector<double> distinct = values;
    std::sort(distinct.begin(), distinct.end());
    distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
    if (decades < 1.5 && distinct.size() <= 12) {
      // Less than two decades: label the data's own values (N = 10, 20, 40), not a lone power of ten.
      gp += fmt::format("set format {} '%g'\nset {}tics ({:.6g})\nset m{}tics default\n", name, name, fmt::join(distinct, ", "), name);
    } else if (decades > 6) {
      // At most about six labels: at the report's 12-point-or-more text, one a decade crowds a panel.
      const int step = static_cast<int>(std::ceil(decades / 6));
      gp += fmt::format("set {}tics 1e{}\nset m{}tics 1\n", name, step, name);
    } else {
      gp += fmt::format("set {}tics autofreq\nset m{}tics default\n", name, name);
    }
  } else if (high > low) {
    const double margin = (high - low) / 20;
    gp += fmt::format("set {}range [{:.6g}:{:.6g}]\n", name, low - margin, high + margin);
  } else {
    gp += fmt::format("set {}range [{:.6g}:{:.6g}]\n", name, low - 1, high + 1);
  }
  return gp;
}

std::string plot_commands(const plot_description& p) {
  std::string gp;
  const bool shared_legend = p.panels.size() > 1;
  const std::size_t columns = static_cast<std::size_t>(std::max(1, p.columns));
  const std::size_t rows = (p.panels.size() + columns - 1) / columns;
  // Several panels: placed by hand in a grid left of a legend column (plot_width()).
  const double legend_fraction = shared_legend ? static_cast<double>(legend_width) / plot_width(p) : 0;
  const double panel_width = (1 - legend_fraction) / static_cast<double>(columns), panel_height = 1.0 / static_cast<double>(rows);
  if (shared_legend) gp += "set multiplot\n";
  std::size_t block = 0;
  std::vector<const series*> legend;  // each title once, in order of appearance
  bool labelled_tics = false;
  for (std::size_t k = 0; k < p.panels.size(); ++k) {
    const panel& pan = p.panels[k];
    if (shared_legend) {
      gp += fmt::format("set origin {:.4f},{:.4f}\nset size {:.4f},{:.4f}\n", static_cast<double>(k % columns) * panel_width,
                        1 - static_cast<double>(k / columns + 1) * panel_height, panel_width, panel_height);
    }
    // A panel after one with labelled tics starts from gnuplot's own again.
    if (labelled_tics) gp += "set xtics autofreq\nset ytics autofreq\nset mxtics default\nset mytics default\n";
    gp += "set title " + gp_quote(pan.title) + "\n";
    const bool log10_y = drawn_as_log10(pan);
    gp += "set xlabel " + gp_quote(pan.x.label) + "\nset ylabel " +
          gp_quote(log10_y ? "log10 of " + pan.y.label + " (beyond double's range)" : pan.y.label) + "\n";
    gp += pan.x.log ? "set logscale x\nset format x '10^{%L}'\n" : "unset logscale x\nset format x '%g'\n";
    gp += pan.y.log && !log10_y ? "set logscale y\nset format y '10^{%L}'\n" : "unset logscale y\nset format y '%g'\n";
    gp += shared_legend ? "unset key\n" : "set key " + pan.key + "\n";
    // Both ranges fitted to the data curves (guides such as slopes and floors are clipped to them).
    std::vector<double> xs, ys;
    for (const series& s : pan.curves) {
      if (s.reference) continue;
      for (const auto& [x, y] : drawable_points(pan, s)) {
        xs.push_back(x);
        ys.push_back(y);
      }
    }
    gp += axis_range("x", pan.x, pan.x.log, xs);
    gp += axis_range("y", pan.y, pan.y.log && !log10_y, ys);
    for (const auto& [name, a] : {std::pair<const char*, const axis*>{"x", &pan.x}, {"y", &pan.y}}) {
      if (a->tics.empty()) continue;
      std::vector<std::string> labelled;
      for (const auto& [at, label] : a->tics) labelled.push_back(fmt::format("{} {:.6g}", gp_quote(label), at));
      gp += fmt::format("set {}tics ({})\nset m{}tics 1\n", name, fmt::join(labelled, ", "), name);
      labelled_tics = true;
    }
    std::vector<std::string> curves;
    for (const series& s : pan.curves) {
      if (drawable_points(pan, s).empty()) continue;
      const std::size_t index = block++;
      curves.push_back(fmt::format("'{}.dat' index {} u 1:2 {} t {}", p.name, index, curve_style(s), gp_quote(s.title)));
      if (std::none_of(legend.begin(), legend.end(), [&](const series* seen) { return seen->title == s.title; })) {
        legend.push_back(&s);
      }
    }
    if (curves.empty()) {
      gp += "set label 1 'no point within double''s range' at graph 0.5, 0.5 center\nunset logscale xy\n"
            "plot [0:1] [0:1] -1 notitle\nunset label 1\n";
    } else {
      gp += "plot " + fmt::format("{}", fmt::join(curves, ", \\\n     ")) + "\n";
    }
  }
  if (shared_legend) {
    // The legend: an empty plot in the right-hand column, one key entry per curve title.
    gp += fmt::format("set origin {:.4f},0\nset size {:.4f},1\nunset title\nunset xlabel\nunset ylabel\nunset logscale xy\n"
                      "unset border\nunset tics\nset xrange [0:1]\nset yrange [0:1]\n"
                      "set key at screen {:.4f},0.97 left top Left reverse samplen 3 spacing 1.3\n",
                      1 - legend_fraction, legend_fraction, 1 - legend_fraction + 0.01);
    std::vector<std::string> entries;
    for (const series* s : legend) entries.push_back(fmt::format("NaN {} t {}", curve_style(*s), gp_quote(s->title)));
    gp += "plot " + fmt::format("{}", fmt::join(entries, ", \\\n     ")) + "\n";
    gp += "unset multiplot\n";
  }
  return gp;
}

}  // namespace

std::size_t points_not_drawn(const plot_description& p) {
  std::size_t n = 0;
  for (const panel& pan : p.panels) {
    for (const series& s : pan.curves) {
      std::size_t values = 0;  // faults are reported in the tables; count only values that exist
      for (std::size_t k = 0; k < s.x.size(); ++k) values += !s.x[k].is_fault() && !s.y[k].is_fault();
      n += values - std::min(values, drawable_points(pan, s).size());
    }
  }
  return n;
}

static std::vector<std::string> panels_drawn_as_log10(const plot_description& p) {
  std::vector<std::string> titles;
  for (const panel& pan : p.panels) {
    if (drawn_as_log10(pan)) titles.push_back(pan.title);
  }
  return titles;
}

namespace {

bool is_timing(const section_block& b) {
  if (const table* t = std::get_if<table>(&b)) return t->timing;
  if (const plot_description* p = std::get_if<plot_description>(&b)) return p->timing;
  return false;
}

/// The blocks of a section in Markdown: those that hold run times (`timing`) or the others.
std::string blocks_markdown(const section_result& s, bool timing) {
  std::string md;
  for (const section_block& b : s.blocks) {
    if (is_timing(b) != timing) continue;
    if (const prose* p = std::get_if<prose>(&b)) {
      md += p->markdown + "\n\n";
    } else if (const table* t = std::get_if<table>(&b)) {
      if (t->markdown) md += table_markdown(*t);
      if (!t->csv_file.empty()) md += "Data: " + t->csv_file + " (every digit computed).\n\n";
    } else if (const plot_description* p = std::get_if<plot_description>(&b)) {
      md += fmt::format("![{}]({}.svg)\n\n*{}*", markdown_escaped(p->caption), p->name, markdown_escaped(p->caption));
      const std::vector<std::string> log10_panels = panels_drawn_as_log10(*p);
      if (!log10_panels.empty()) {
        md += fmt::format(" Panel{} {} show{} log10 of the values, which lie beyond double's range.", log10_panels.size() == 1 ? "" : "s",
                          fmt::join(log10_panels, ", "), log10_panels.size() == 1 ? "s" : "");
      }
      const std::size_t missing = points_not_drawn(*p);
      if (missing) md += fmt::format(" ({} point{} beyond double's range, not drawn; every value is in the tables.)", missing,
                                     missing == 1 ? "" : "s");
      md += "\n\n";
    }
  }
  return md;
}

}  // namespace

bool has_timing(const section_result& s) {
  return std::any_of(s.blocks.begin(), s.blocks.end(), is_timing);
}

json section_json(const section_result& s) {
  json j = json::object();
  j["title"] = s.title;
  if (!s.conventions.empty()) j["conventions"] = s.conventions;
  json files = json::array();
  for (const section_block& b : s.blocks) {
    if (const table* t = std::get_if<table>(&b)) {
      if (t->json && !t->timing) j[t->key] = table_json(*t);
    }
  }
  for (const data_file& f : section_files(s)) {
    if (!f.timing) files.push_back(f.name);
  }
  j["files"] = files;
  if (!s.expectations.empty()) {
    json expectations = json::array();
    for (const expectation& e : s.expectations) {
      expectations.push_back({{"key", e.key}, {"statement", e.statement}, {"predicted", e.predicted}, {"observed", e.observed}, {"holds", e.holds}});
    }
    j["expectations"] = expectations;
  }
  return j;
}

json section_timing_json(const section_result& s) {
  json j = json::object();
  if (!has_timing(s)) return j;
  if (!s.timing_conventions.empty()) j["conventions"] = s.timing_conventions;
  for (const section_block& b : s.blocks) {
    if (const table* t = std::get_if<table>(&b); t && t->timing) j[t->key] = table_json(*t);
  }
  return j;
}

std::string section_markdown(const section_result& s) {
  std::string md = "## " + s.title + "\n\n" + blocks_markdown(s, false);
  if (!s.expectations.empty()) {
    const auto held = std::count_if(s.expectations.begin(), s.expectations.end(), [](const expectation& e) { return e.holds; });
    md += fmt::format("**Expectations of this section: {} of {} hold.** Each is predicted without the run and is a JUnit testcase; "
                      "one that fails fails the run.\n\n",
                      held, s.expectations.size());
    for (const expectation& e : s.expectations) {
      md += fmt::format("- {} `{}`: {} Predicted: {}. Observed: {}.\n", e.holds ? "✓" : "✗ **fails**", e.key, markdown_escaped(e.statement),
                        markdown_escaped(e.predicted), markdown_escaped(e.observed));
    }
    md += "\n";
  }
  if (has_timing(s)) md += "Run times of this section: [timing.md](timing.md) (kept apart, so that every other file of the report is the same from run to run).\n\n";
  return md;
}

int plot_width(const plot_description& p) { return p.width + (p.panels.size() > 1 ? legend_width : 0); }

std::string section_timing_markdown(const section_result& s) {
  return has_timing(s) ? "## " + s.title + ": run times\n\n" + blocks_markdown(s, true) : std::string();
}

std::vector<data_file> section_files(const section_result& s) {
  std::vector<data_file> files;
  for (const section_block& b : s.blocks) {
    if (const table* t = std::get_if<table>(&b); t && !t->csv_file.empty()) files.push_back({t->csv_file, table_csv(*t), t->timing});
    if (const plot_description* p = std::get_if<plot_description>(&b)) files.push_back({p->name + ".dat", plot_data(*p), p->timing});
  }
  return files;
}

std::vector<plot_spec> section_plots(const section_result& s) {
  std::vector<plot_spec> plots;
  for (const section_block& b : s.blocks) {
    if (const plot_description* p = std::get_if<plot_description>(&b)) {
      plots.push_back({p->name, p->caption, plot_commands(*p), plot_width(*p), p->height, p->timing});
    }
  }
  return plots;
}

}  // namespace simpson::verify
