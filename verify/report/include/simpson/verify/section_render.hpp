#pragma once
// The one writer of the result model: report.json members, report.md text, CSV files, gnuplot
// data files and scripts, all from a section_result. Figures keep every digit in JSON and CSV and
// are rounded only for Markdown; faults print as their words everywhere (gnuplot skips them).

#include <simpson/verify/result_model.hpp>

#include <string>
#include <vector>

namespace simpson::verify {

struct data_file {
  std::string name;  // e.g. "work_precision.csv"
  std::string content;
  bool timing = false;  // holds run times (differs from run to run)
};

/// A plot ready for gnuplot: commands that read the section's data files; the writer adds the
/// terminal and output lines and draws <name>.svg and <name>.png.
struct plot_spec {
  std::string name;
  std::string caption;
  std::string commands;
  int width = 800;
  int height = 500;
  bool timing = false;  // plots run times (differs from run to run)
};

/// A figure in report.json: a number when it was computed in double or is an integer, the decimal
/// text (every digit of its precision) otherwise, true/false for a flag, the word for a fault.
json figure_json(const figure& f);

/// A Markdown table cell: markdown_escaped (every syntax character escaped, '|' among them, newlines folded).
std::string markdown_cell(const std::string& text);

/// The section's member of report.json: its conventions, each table that is not a timing table as
/// a list of row objects, and the files it writes that do not hold run times.
json section_json(const section_result& s);

/// Its timing tables, each as a list of row objects (timing.json); empty when it has none.
json section_timing_json(const section_result& s);

/// True when the section has timing tables or plots.
bool has_timing(const section_result& s);

/// The section in report.md: its title, prose, tables and plot links, in order, without the
/// timing blocks (a link to timing.md stands for them).
std::string section_markdown(const section_result& s);

/// Its timing blocks for timing.md under "## <title>: run times"; empty when it has none.
std::string section_timing_markdown(const section_result& s);

/// CSV files of its tables, and one .dat file per plot.
std::vector<data_file> section_files(const section_result& s);

/// The gnuplot script of each plot.
std::vector<plot_spec> section_plots(const section_result& s);

/// The width in pixels of a plot's image: its panels', and with several panels the legend column.
int plot_width(const plot_description& p);

/// Points of a plot left out because they are faults or outside double's range (gnuplot's).
std::size_t points_not_drawn(const plot_description& p);

}  // namespace simpson::verify
