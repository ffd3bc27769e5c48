#include <simpson/verify/figure.hpp>

#include <fmt/format.h>

#include <cstdlib>
#include <stdexcept>

namespace simpson::verify {

std::string round_decimal(const std::string& text, int digits) {
  // Split [-]int[.frac][e±exp] into its significant digits and a decimal exponent.
  std::size_t k = 0;
  const bool negative = !text.empty() && text[0] == '-';
  if (negative || (!text.empty() && text[0] == '+')) ++k;
  std::string mantissa;
  long long point = -1;  // digits before the decimal point
  for (; k < text.size() && text[k] != 'e' && text[k] != 'E'; ++k) {
    if (text[k] == '.') {
      point = static_cast<long long>(mantissa.size());
    } else if (text[k] >= '0' && text[k] <= '9') {
      mantissa += text[k];
    } else {
      throw std::invalid_argument("round_decimal: not a decimal number: '" + text + "'");
    }
  }
  if (mantissa.empty()) throw std::invalid_argument("round_decimal: not a decimal number: '" + text + "'");
  if (point < 0) point = static_cast<long long>(mantissa.size());
  long long exponent = 0;
  if (k < text.size()) exponent = std::stoll(text.substr(k + 1));
  // value = 0.mantissa × 10^(point + exponent); drop leading zeros.
  const std::size_t first = mantissa.find_first_not_of('0');
  if (digits < 1) digits = 1;
  if (first == std::string::npos) {
    return digits > 1 ? "0." + std::string(static_cast<std::size_t>(digits - 1), '0') + "e+00" : "0e+00";
  }
  long long decimal_exponent = point + exponent - static_cast<long long>(first) - 1;  // of the leading digit
  std::string sig = mantissa.substr(first);
  if (static_cast<int>(sig.size()) > digits) {
    const bool round_up = sig[static_cast<std::size_t>(digits)] >= '5';
    sig.resize(static_cast<std::size_t>(digits));
    if (round_up) {
      int j = digits - 1;
      for (; j >= 0 && sig[static_cast<std::size_t>(j)] == '9'; --j) sig[static_cast<std::size_t>(j)] = '0';
      if (j >= 0) {
        ++sig[static_cast<std::size_t>(j)];
      } else {
        sig.insert(sig.begin(), '1');
        sig.pop_back();
        ++decimal_exponent;
      }
    }
  }
  sig.resize(static_cast<std::size_t>(digits), '0');
  std::string out = negative ? "-" : "";
  out += sig[0];
  if (digits > 1) out += "." + sig.substr(1);
  const long long magnitude = decimal_exponent < 0 ? -decimal_exponent : decimal_exponent;
  out += decimal_exponent < 0 ? "e-" : "e+";
  out += (magnitude < 10 ? "0" : "") + std::to_string(magnitude);
  return out;
}

std::string fixed_decimal(const std::string& text, int decimals) {
  const std::string zero = decimals > 0 ? "0." + std::string(static_cast<std::size_t>(decimals), '0') : "0";
  // The decimal exponent of the leading digit, from the value itself (a one-digit probe would take
  // 0.9975's for 1's), then that many digits before the point and `decimals` after it.
  const std::string exact = round_decimal(text, 40);
  if (exact.find_first_not_of("-0.e+") == std::string::npos) return zero;
  const long long exponent = std::stoll(exact.substr(exact.find('e') + 1));
  const long long keep = exponent + 1 + decimals;  // digits from the leading one to the last decimal
  if (keep < 0) return zero;
  bool negative = exact[0] == '-';
  long long leading = exponent;
  std::string digits;
  if (keep == 0) {  // below one unit of the last decimal: 0, or that unit (0.006 to two decimals is 0.01)
    if (exact[negative ? 1 : 0] < '5') return zero;
    digits = "1";
    leading = exponent + 1;
  } else {
    const std::string rounded = round_decimal(text, static_cast<int>(keep));
    negative = rounded[0] == '-';
    leading = std::stoll(rounded.substr(rounded.find('e') + 1));
    for (const char c : rounded.substr(0, rounded.find('e'))) {
      if (c >= '0' && c <= '9') digits += c;
    }
    if (leading != exponent) digits += '0';  // carried into a new leading digit (9.96 → 10.0): one digit more
  }
  std::string out;
  if (leading < 0) {
    out = "0." + std::string(static_cast<std::size_t>(-leading - 1), '0') + digits;
  } else {
    const std::size_t whole = static_cast<std::size_t>(leading + 1);
    out = digits.substr(0, whole) + (decimals > 0 ? "." + digits.substr(whole) : "");
  }
  return (negative ? "-" : "") + out;
}

namespace {
/// The significant digits of a decimal text ("1.4427e-14": 5; "0": 0).
int significant_digits(const std::string& text) {
  int count = 0;
  bool leading = true;
  for (const char c : text.substr(0, text.find_first_of("eE"))) {
    if (c < '0' || c > '9') continue;
    if (leading && c == '0') continue;
    leading = false;
    ++count;
  }
  return count;
}
}  // namespace

std::string display(const figure& f, int digits, bool fixed) {
  if (f.what() != figure::kind::number) return f.value();
  if (digits == 0) return f.as_computed_double() ? fmt::format("{}", *f.as_computed_double()) : f.full_text();
  if (!f.radius().empty() && (fixed || significant_digits(f.value()) < digits)) return f.full_text();
  return fixed ? fixed_decimal(f.value(), digits) : round_decimal(f.value(), digits);
}

std::string display_value(const figure& f, int digits, bool fixed) {
  if (f.what() == figure::kind::number && digits != 0 && !f.radius().empty() && (fixed || significant_digits(f.value()) < digits)) return f.value();
  return display(f, digits, fixed);
}

std::optional<double> figure::plottable() const {
  if (double_) return std::isfinite(*double_) && (*double_ == 0 || std::abs(*double_) >= std::numeric_limits<double>::min())
                          ? double_
                          : std::nullopt;
  if (kind_ != kind::number && kind_ != kind::integer) return std::nullopt;
  // Only to draw: strtod's rounding is harmless there, and values beyond double's range are left out.
  char* end = nullptr;
  const double v = std::strtod(text_.c_str(), &end);
  if (end == text_.c_str() || !std::isfinite(v)) return std::nullopt;
  if (v == 0 && round_decimal(text_, 1) != "0e+00") return std::nullopt;  // lost below double's range
  if (v != 0 && std::abs(v) < std::numeric_limits<double>::min()) return std::nullopt;
  return v;
}

std::optional<double> figure::log10_magnitude() const {
  if (kind_ != kind::number && kind_ != kind::integer) return std::nullopt;
  const std::string r = round_decimal(text_, 17);
  const std::size_t e = r.find('e');
  const double mantissa = std::abs(std::strtod(r.substr(0, e).c_str(), nullptr));
  if (!(mantissa > 0)) return std::nullopt;
  return static_cast<double>(std::stoll(r.substr(e + 1))) + std::log10(mantissa);
}

}  // namespace simpson::verify
