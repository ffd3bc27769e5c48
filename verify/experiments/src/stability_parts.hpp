#pragma once
// The parts of the stability section (stability_section.cpp assembles them).

#include <simpson/verify/result_model.hpp>
#include <simpson/verify/stability_analysis.hpp>

#include <string>
#include <utility>
#include <vector>

namespace simpson::verify::detail {

/// The class of a running maximum's growth over three decades from its log-log exponent: bounded
/// (< 0.5), linear ([0.5, 1.5), a Jordan block), exponential (> 3), or "none of these".
std::string growth_class(double exponent);

/// At and around each exact endpoint of `report`: Φ₃ⁿ y₀ in closed form for n up to `last_power`,
/// the growth fitted, a table, and one expectation per row (the fitted class is the predicted one).
void add_endpoint_growth(const stability_report& report, long long last_power, section_result& out);

/// The x tics of an ωh axis up to `last`: Φ₃'s band ends from `region` (2√2, 2√3, 2√6) and the
/// integers not crowding them.
std::vector<std::pair<double, std::string>> band_end_tics(const stability_report& region, double last);

/// The plot of each scheme's spectral radius against ωh, Φ₃'s band ends (from `region`) on its axis.
void add_spectral_radius(const stability_report& region, section_result& out);

/// The stiff chain at each ratio r of its frequencies, its fast modes placed mid-band in each band of
/// `region`: the exact prediction, a run of 2^doublings steps, a table and one expectation per row.
void add_stiff_chain(const stability_report& region, const std::vector<double>& ratios, int doublings, section_result& out);

}  // namespace simpson::verify::detail
