// What a reader of the plots needs, checked on every plot of the quick scene: two guides of one
// panel (slopes, a round-off floor) are told apart; a measured curve and its prediction both show;
// every scheme curve has markers (a plot against run time scatters its points); axes say what they
// plot, with ω, not "omega".

#include <simpson/verify/report.hpp>
#include <simpson/verify/scene.hpp>

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <tuple>
#include <variant>

namespace simpson::verify {
namespace {

std::vector<plot_description> quick_plots() {
  scene s = load_scene("quick", paper_book());
  s.claims.clear();
  const run_record r = run(s);
  std::vector<plot_description> plots;
  for (const section_result& section : r.sections) {
    for (const section_block& b : section.blocks) {
      if (const plot_description* p = std::get_if<plot_description>(&b)) plots.push_back(*p);
    }
  }
  return plots;
}

TEST(PlotStyle, GuidesOfAPanelDifferAndLabelsSayWhatTheyPlot) {
  const std::vector<plot_description> plots = quick_plots();
  ASSERT_GE(plots.size(), 7u);
  for (const plot_description& p : plots) {
    for (const panel& pan : p.panels) {
      std::set<std::tuple<int, int>> guide_looks;
      for (const series& s : pan.curves) {
        if (s.style != line_style::dashed) continue;
        const int dash = s.dash == 1 ? 2 : s.dash;  // as section_render draws a guide
        EXPECT_TRUE(guide_looks.insert({s.color, dash}).second)
            << p.name << ", panel " << pan.title << ": guide '" << s.title << "' looks like another guide";
      }
      for (const std::string& label : {pan.x.label, pan.y.label, pan.title}) {
        EXPECT_EQ(label.find("omega"), std::string::npos) << p.name << ": '" << label << "' (write ω)";
      }
      EXPECT_NE(pan.y.label, "max error") << p.name << ": max error of what?";
      EXPECT_EQ(pan.y.label.find("m omega units"), std::string::npos) << p.name;
    }
  }
}

TEST(PlotStyle, PredictionsShowBesideMeasurementsAndSchemesHaveMarkers) {
  for (const plot_description& p : quick_plots()) {
    for (const panel& pan : p.panels) {
      for (const series& s : pan.curves) {
        if (s.title.find(" measured") != std::string::npos) {
          // A measured curve drawn as a line lies under its prediction; as markers both show.
          EXPECT_EQ(s.style, line_style::points) << p.name << ": " << s.title;
        }
        if (p.name.rfind("work_precision", 0) == 0 && !s.reference) {
          EXPECT_NE(s.style, line_style::lines) << p.name << ": " << s.title << " has no markers";
        }
      }
    }
  }
}

}  // namespace
}  // namespace simpson::verify
