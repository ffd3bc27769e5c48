// Every section at mpfr:3000 (small sizes): figures far below double's range are carried whole
// from the computation to every file, and they are right.

#include <simpson/verify/report.hpp>

#include "report_tree.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

namespace simpson::verify {
namespace {

/// The decimal exponent of a figure's text ("3.1e-2996" → -2996).
long long exponent_of(const std::string& decimal) { return std::stoll(decimal.substr(decimal.find('e') + 1)); }

const json& row_where(const json& rows, const std::string& key, const std::string& value, const std::string& key2 = "",
                      const json& value2 = {}) {
  for (const json& r : rows) {
    if (r.value(key, "") == value && (key2.empty() || r[key2] == value2)) return r;
  }
  throw std::out_of_range("no row " + key + " = " + value);
}

TEST(HighPrecision, EverySectionAtMpfr3000KeepsItsDigitsAndIsRight) {
  const scene s = parse_scene(R"({"name": "mpfr3000",
      "table1": {"N": [10, 20]},
      "work_precision": {"schemes": ["simpson", "newmark"], "precisions": ["mpfr:3000"], "N": [16, 64],
                         "max_runs": 1, "max_seconds": 0.05},
      "stability": {"precisions": ["double", "mpfr:3000"], "stiff_ratios": [1e3], "stiff_doublings": 12, "omega_h": [1e-8, 1e-2, 1],
                    "masses": [1e-300, 1, 1e300], "steps": 100},
      "long_time": {"steps_double": 10000, "steps_mpfr": 1000, "mpfr_digits": 3000, "windows": 10}})",
                              "mpfr3000", paper_book());
  const run_record r = run(s);
  const json j = report_json(r);

  // long_time: H_d's drift over 1000 steps in mpfr:3000 is a few hundred eps (eps = 10^-2999), not
  // `underflow`. It is an enclosure (H_d evaluated in MPFI on the iterates, 3010 digits): only the
  // digits it guarantees, about ten at this size, and its radius.
  const json& drift = row_where(j["experiments"]["long_time"]["rows"], "precision", "mpfr:3000", "scheme", "simpson");
  ASSERT_TRUE(drift["max_relative_energy_change"].is_string()) << drift.dump();
  const std::string d = drift["max_relative_energy_change"].get<std::string>();
  const std::size_t plus_minus = d.find(" ± ");
  ASSERT_NE(plus_minus, std::string::npos) << d;
  const std::string midpoint = d.substr(0, plus_minus), radius = d.substr(plus_minus + std::string(" ± ").size());
  EXPECT_GE(exponent_of(midpoint), -3000);
  EXPECT_LE(exponent_of(midpoint), -2994);
  EXPECT_LE(exponent_of(radius), exponent_of(midpoint) - 8) << d;  // at least 8 digits guaranteed
  EXPECT_EQ(drift["status"], "ok");

  // stability: the digits of c reach the thousands against the reference (computed with more
  // digits than the run), less what the formula cancels: c = T_h/(θ⁴q) with T_h = O(θ⁴ q) a sum
  // of terms of size q/h², so about 6 log10(1/ωh) + log10(1440) digits are lost, plus a few roundings.
  for (const json& row : j["experiments"]["stability"]["extreme_omega_h"]) {
    if (row["precision"] != "mpfr:3000") continue;
    const double lost = 6 * std::log10(1 / row["omega_h"].get<double>()) + std::log10(1440.0) + 2;
    EXPECT_GE(row["digits_of_c"].get<double>(), 3000 - lost) << row["omega_h"];
    EXPECT_LE(row["digits_of_c"].get<double>(), 3000) << row["omega_h"];
    EXPECT_EQ(row["status"], "ok");
  }
  // m = 1e300 is an ordinary mass in mpfr:3000 (it overflows H only in double).
  for (const json& row : j["experiments"]["stability"]["extreme_masses"]) {
    if (row["precision"] == "mpfr:3000") {
      EXPECT_EQ(row["status"], "ok") << row["m"];
    }
  }
  // work_precision: errors at mpfr:3000 are the method's, and the round-off floor 100 N eps is
  // carried as a number near 1e-2996 (this used to end the run with `stod`).
  for (const json& row : j["experiments"]["work_precision"]["rows"]) EXPECT_EQ(row["status"], "ok");

  const std::filesystem::path dir = std::filesystem::temp_directory_path() / "simpson-high-precision-test";
  std::filesystem::remove_all(dir);
  write_report_files(dir, r);
  test::expect_no_bare_non_finite(dir);
  test::expect_html_tables_rendered(dir);
  // The Markdown shows the value as what it is.
  EXPECT_NE(test::read_text(dir / "report.md").find("e-299"), std::string::npos);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace simpson::verify
