#pragma once
// The one list of precisions: name, epsilon, and a way to run generic code in each by name.
// Used alike by the core's tests, the claims ledger, the property tests and the reports. The
// traits of a scalar (eps, is_exact_v, to_string) are scalar_traits.hpp's: formulas need only those.

#include <simpson/precision_types.hpp>
#include <simpson/scalar_traits.hpp>

#include <cerrno>
#include <cstdlib>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace simpson {

/// Sets the working precision of newly created `mpfr` values for the lifetime of the object,
/// then restores the previous one. Values keep the precision they were created with.
class scoped_mpfr_digits {
 public:
  explicit scoped_mpfr_digits(unsigned digits10) : saved_(mpfr::default_precision()) {
    mpfr::default_precision(digits10);
  }
  ~scoped_mpfr_digits() { mpfr::default_precision(saved_); }
  scoped_mpfr_digits(const scoped_mpfr_digits&) = delete;
  scoped_mpfr_digits& operator=(const scoped_mpfr_digits&) = delete;

 private:
  unsigned saved_;
};

enum class precision_kind { float64, extended, float128, bin50, bin100, mpfr, rational };

/// One entry of the precision list: a scalar type, and for mpfr its run-time digits.
class precision {
 public:
  static constexpr unsigned min_mpfr_digits = 30;
  static constexpr unsigned max_mpfr_digits = 100000;

  /// Parses "double", "long double" (or "long-double"), "float128", "bin50", "bin100",
  /// "mpfr:D" with min_mpfr_digits <= D <= max_mpfr_digits, "rational".
  /// Throws std::invalid_argument naming the text when it is none of these.
  static precision parse(std::string_view spec) {
    for (const auto& [name, kind] : fixed_names()) {
      if (spec == name) return precision(kind, 0);
    }
    if (spec == "long-double") return precision(precision_kind::extended, 0);
    constexpr std::string_view prefix = "mpfr:";
    if (spec.substr(0, prefix.size()) == prefix) {
      const std::string digits(spec.substr(prefix.size()));
      char* end = nullptr;
      errno = 0;
      const unsigned long d = digits.empty() ? 0 : std::strtoul(digits.c_str(), &end, 10);
      if (digits.empty() || *end != '\0' || errno != 0 || digits.front() == '-' || d < min_mpfr_digits ||
          d > max_mpfr_digits) {
        throw std::invalid_argument("precision '" + std::string(spec) + "': mpfr digits must be an integer from " +
                                    std::to_string(min_mpfr_digits) + " to " + std::to_string(max_mpfr_digits));
      }
      return mpfr_digits(static_cast<unsigned>(d));
    }
    throw std::invalid_argument("unknown precision '" + std::string(spec) +
                                "' (expected double, long double, float128, bin50, bin100, mpfr:D, rational)");
  }

  /// mpfr with `digits10` decimal digits; throws std::invalid_argument outside the allowed range.
  static precision mpfr_digits(unsigned digits10) {
    if (digits10 < min_mpfr_digits || digits10 > max_mpfr_digits) {
      throw std::invalid_argument("precision mpfr:" + std::to_string(digits10) + ": digits must be from " +
                                  std::to_string(min_mpfr_digits) + " to " + std::to_string(max_mpfr_digits));
    }
    return precision(precision_kind::mpfr, digits10);
  }

  precision_kind kind() const noexcept { return kind_; }
  bool exact() const noexcept { return kind_ == precision_kind::rational; }

  std::string name() const {
    if (kind_ == precision_kind::mpfr) return "mpfr:" + std::to_string(mpfr_digits_);
    for (const auto& [name, kind] : fixed_names()) {
      if (kind == kind_) return std::string(name);
    }
    return "?";
  }

  /// Runs f(precision_tag<Real>{}) with Real this precision's type; for mpfr the working
  /// digits are set for the duration of the call. Returns what f returns.
  template <class F>
  decltype(auto) visit(F&& f) const {
    switch (kind_) {
      case precision_kind::float64: return std::forward<F>(f)(precision_tag<double>{});
      case precision_kind::extended: return std::forward<F>(f)(precision_tag<long double>{});
      case precision_kind::float128: return std::forward<F>(f)(precision_tag<float128>{});
      case precision_kind::bin50: return std::forward<F>(f)(precision_tag<bin50>{});
      case precision_kind::bin100: return std::forward<F>(f)(precision_tag<bin100>{});
      case precision_kind::mpfr: {
        const scoped_mpfr_digits digits(mpfr_digits_);
        return std::forward<F>(f)(precision_tag<mpfr>{});
      }
      case precision_kind::rational: break;
    }
    return std::forward<F>(f)(precision_tag<rational>{});
  }

  /// Unit round-off in decimal ("0" for rational), 3 significant digits.
  std::string epsilon() const {
    return visit([](auto tag) -> std::string {
      using Real = typename decltype(tag)::type;
      if constexpr (is_exact_v<Real>) {
        return "0";
      } else {
        return to_string(eps<Real>(), 3);
      }
    });
  }

  /// Significant decimal digits carried (for reports): 0 for rational.
  unsigned digits10() const {
    if (kind_ == precision_kind::mpfr) return mpfr_digits_;
    return visit([](auto tag) -> unsigned {
      using Real = typename decltype(tag)::type;
      return is_exact_v<Real> ? 0u : static_cast<unsigned>(std::numeric_limits<Real>::digits10);
    });
  }

  friend bool operator==(const precision& a, const precision& b) {
    return a.kind_ == b.kind_ && a.mpfr_digits_ == b.mpfr_digits_;
  }

 private:
  precision(precision_kind kind, unsigned mpfr_digits) : kind_(kind), mpfr_digits_(mpfr_digits) {}

  static const std::vector<std::pair<std::string_view, precision_kind>>& fixed_names() {
    static const std::vector<std::pair<std::string_view, precision_kind>> names = {
        {"double", precision_kind::float64}, {"long double", precision_kind::extended},
        {"float128", precision_kind::float128}, {"bin50", precision_kind::bin50},
        {"bin100", precision_kind::bin100},   {"rational", precision_kind::rational}};
    return names;
  }

  precision_kind kind_;
  unsigned mpfr_digits_;
};

/// The precisions every default run covers, coarsest first: the ladder on which residuals
/// must fall with the precision, ending with exact rationals.
inline std::vector<precision> default_precisions() {
  return {precision::parse("double"),   precision::parse("long double"), precision::parse("float128"),
          precision::parse("bin50"),    precision::mpfr_digits(50),       precision::parse("bin100"),
          precision::mpfr_digits(100), precision::mpfr_digits(1000),     precision::parse("rational")};
}

}  // namespace simpson
