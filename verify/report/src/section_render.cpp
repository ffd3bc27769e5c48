#include <simpson/verify/section_render.hpp>

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

namespace simpson::verify {

json figure_json(const figure& f) {
  switch (f.what()) {
    case figure::kind::empty: return "";
    case figure::kind::number:
      if (f.as_computed_double()) return *f.as_computed_double();
      return f.value();
    case figure::kind::integer: return std::stoll(f.value());
    case figure::kind::flag: return f.value() == "yes";
    case figure::kind::exact:
    case figure::kind::text:
    case figure::kind::fault: return f.value();
  }
  return f.value();
}

std::string markdown_cell(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '|') {
      out += "\\|";
    } else if (c == '\n') {
      out += ' ';
    } else {
      out += c;
    }
  }
  return out;
}

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
      if (row[k].what() == figure::kind::empty) continue;
      if (t.columns[k].timing) {
        r["timing"][t.columns[k].key] = figure_json(row[k]);
      } else {
        r[t.columns[k].key] = figure_json(row[k]);
      }
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
  // A timing column carries its unit in each cell ("1.2e-03 s", "3 runs"), so that comparisons
  // of reports can mask run times wherever they stand.
  for (const column& c : t.columns) {
    md += " " + markdown_cell(c.unit.empty() || c.timing ? c.header : c.header + " (" + c.unit + ")") + " |";
  }
  md += "\n|";
  for (std::size_t k = 0; k < t.columns.size(); ++k) md += "---|";
  md += "\n";
  for (const table_row& row : t.rows) {
    md += "|";
    for (std::size_t k = 0; k < t.columns.size(); ++k) {
      const column& c = t.columns[k];
      std::string text = display(row[k], c.digits, c.fixed);
      if (c.timing && !c.unit.empty() && row[k].what() != figure::kind::empty) text += " " + c.unit;
      md += " " + markdown_cell(text) + " |";
    }
    md += "\n";
  }
  return md + "\n";
}

std::string table_csv(const table& t) {
  std::string csv;
  for (std::size_t k = 0; k < t.columns.size(); ++k) csv += (k ? "," : "") + csv_field(t.columns[k].key);
  csv += "\n";
  for (const table_row& row : t.rows) {
    for (std::size_t k = 0; k < t.columns.size(); ++k) csv += (k ? "," : "") + csv_field(row[k].value());
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

std::string plot_commands(const plot_description& p) {
  std::string gp;
  const std::size_t rows = (p.panels.size() + static_cast<std::size_t>(p.columns) - 1) / static_cast<std::size_t>(p.columns);
  if (p.panels.size() > 1) gp += fmt::format("set multiplot layout {},{}\n", rows, p.columns);
  std::size_t block = 0;
  for (const panel& pan : p.panels) {
    gp += "set title " + gp_quote(pan.title) + "\n";
    const bool log10_y = drawn_as_log10(pan);
    gp += "set xlabel " + gp_quote(pan.x.label) + "\nset ylabel " +
          gp_quote(log10_y ? "log10 of " + pan.y.label + " (beyond double's range)" : pan.y.label) + "\n";
    gp += pan.x.log ? "set logscale x\nset format x '10^{%L}'\n" : "unset logscale x\nset format x '%g'\n";
    gp += pan.y.log && !log10_y ? "set logscale y\nset format y '10^{%L}'\n" : "unset logscale y\nset format y '%g'\n";
    gp += "set key " + pan.key + " font ',8'\n";
    // The y range fitted to the data curves (references are clipped to it), with a margin.
    double low = 0, high = 0;
    bool any = false;
    for (const series& s : pan.curves) {
      if (s.reference) continue;
      for (const auto& point : drawable_points(pan, s)) {
        low = any ? std::min(low, point.second) : point.second;
        high = any ? std::max(high, point.second) : point.second;
        any = true;
      }
    }
    if (any && pan.y.log && !log10_y) {
      gp += fmt::format("set yrange [{:.6g}:{:.6g}]\n", low / 4, high * 4);
    } else if (any && high > low) {
      const double margin = (high - low) / 20;
      gp += fmt::format("set yrange [{:.6g}:{:.6g}]\n", low - margin, high + margin);
    } else {
      gp += "set autoscale y\n";
    }
    std::vector<std::string> curves;
    for (const series& s : pan.curves) {
      if (drawable_points(pan, s).empty()) continue;
      const std::size_t index = block++;
      const char* color = palette[static_cast<std::size_t>(s.color) % std::size(palette)];
      std::string with;
      switch (s.style) {
        case line_style::lines: with = fmt::format("w l lw 1.5 lc rgb '{}'", color); break;
        case line_style::points: with = fmt::format("w p pt {} ps 1.5 lc rgb '{}'", s.point, color); break;
        case line_style::lines_points: with = fmt::format("w lp pt {} lc rgb '{}'", s.point, color); break;
        case line_style::dashed: with = fmt::format("w l dt 2 lc rgb '{}'", color); break;
      }
      curves.push_back(fmt::format("'{}.dat' index {} u 1:2 {} t {}", p.name, index, with, gp_quote(s.title)));
    }
    if (curves.empty()) {
      gp += "set label 1 'no point within double''s range' at graph 0.5, 0.5 center\nunset logscale xy\n"
            "plot [0:1] [0:1] -1 notitle\nunset label 1\n";
    } else {
      gp += "plot " + fmt::format("{}", fmt::join(curves, ", \\\n     ")) + "\n";
    }
  }
  if (p.panels.size() > 1) gp += "unset multiplot\n";
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

json section_json(const section_result& s) {
  json j = json::object();
  j["title"] = s.title;
  if (!s.conventions.empty()) j["conventions"] = s.conventions;
  json files = json::array();
  for (const section_block& b : s.blocks) {
    if (const table* t = std::get_if<table>(&b)) {
      if (t->json) j[t->key] = table_json(*t);
    }
  }
  for (const data_file& f : section_files(s)) files.push_back(f.name);
  j["files"] = files;
  return j;
}

std::string section_markdown(const section_result& s) {
  std::string md = "## " + s.title + "\n\n";
  for (const section_block& b : s.blocks) {
    if (const prose* p = std::get_if<prose>(&b)) {
      md += p->markdown + "\n\n";
    } else if (const table* t = std::get_if<table>(&b)) {
      if (t->markdown) md += table_markdown(*t);
      if (!t->csv_file.empty()) md += "Data: " + t->csv_file + " (every digit computed).\n\n";
    } else if (const plot_description* p = std::get_if<plot_description>(&b)) {
      md += fmt::format("![{}]({}.svg)\n\n*{}*", p->caption, p->name, p->caption);
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

std::vector<data_file> section_files(const section_result& s) {
  std::vector<data_file> files;
  for (const section_block& b : s.blocks) {
    if (const table* t = std::get_if<table>(&b); t && !t->csv_file.empty()) files.push_back({t->csv_file, table_csv(*t)});
    if (const plot_description* p = std::get_if<plot_description>(&b)) files.push_back({p->name + ".dat", plot_data(*p)});
  }
  return files;
}

std::vector<plot_spec> section_plots(const section_result& s) {
  std::vector<plot_spec> plots;
  for (const section_block& b : s.blocks) {
    if (const plot_description* p = std::get_if<plot_description>(&b)) {
      plots.push_back({p->name, p->caption, plot_commands(*p), p->width, p->height});
    }
  }
  return plots;
}

}  // namespace simpson::verify
