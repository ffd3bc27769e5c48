// Rational functions of θ over Q (rational_function.hpp).

#include <simpson/verify/rational_function.hpp>

namespace simpson::verify {
namespace {

polynomial one() { return make_polynomial({rational(1)}); }

polynomial constant(const rational& c) {
  if (c == 0) return polynomial();
  return make_polynomial({c});
}

}  // namespace

polynomial make_polynomial(const std::vector<rational>& coefficients) { return polynomial(coefficients.begin(), coefficients.end()); }

bool is_zero(const polynomial& p) {
  for (std::size_t k = 0; k < p.size(); ++k) {
    if (p[k] != 0) return false;
  }
  return true;
}

long degree(const polynomial& p) {
  for (std::size_t k = p.size(); k-- > 0;) {
    if (p[k] != 0) return static_cast<long>(k);
  }
  return -1;
}

std::string to_string(const polynomial& p, const std::string& var) {
  std::string out;
  for (long k = degree(p); k >= 0; --k) {
    const rational& c = p[static_cast<std::size_t>(k)];
    if (c == 0) continue;
    const bool negative = c < 0;
    const rational magnitude = negative ? rational(-c) : c;
    out += out.empty() ? (negative ? "-" : "") : (negative ? " - " : " + ");
    const bool unit = magnitude == 1 && k > 0;
    if (!unit) out += simpson::to_string(magnitude);
    if (k > 0) out += (unit ? "" : " ") + var + (k > 1 ? "^" + std::to_string(k) : "");
  }
  return out.empty() ? "0" : out;
}

rational_function::rational_function() : numerator_(), denominator_(one()) {}
rational_function::rational_function(int c) : numerator_(constant(rational(c))), denominator_(one()) {}
rational_function::rational_function(const rational& c) : numerator_(constant(c)), denominator_(one()) {}
rational_function::rational_function(polynomial numerator, polynomial denominator)
    : numerator_(std::move(numerator)), denominator_(std::move(denominator)) {
  if (verify::is_zero(denominator_)) throw std::domain_error("simpson::verify::rational_function: zero denominator");
  fold_constant_denominator();
}

rational_function rational_function::variable() { return {make_polynomial({rational(0), rational(1)}), one()}; }

bool rational_function::is_zero() const { return verify::is_zero(numerator_); }

rational rational_function::operator()(const rational& t) const {
  const rational d = denominator_.evaluate(t);
  if (d == 0) throw std::domain_error("simpson::verify::rational_function: pole at " + simpson::to_string(t));
  return numerator_.evaluate(t) / d;
}

rational_function rational_function::operator-() const { return {polynomial() - numerator_, denominator_}; }

rational_function operator+(const rational_function& a, const rational_function& b) {
  if (a.denominator_ == b.denominator_) return {a.numerator_ + b.numerator_, a.denominator_};
  return {a.numerator_ * b.denominator_ + b.numerator_ * a.denominator_, a.denominator_ * b.denominator_};
}
rational_function operator-(const rational_function& a, const rational_function& b) { return a + (-b); }
rational_function operator*(const rational_function& a, const rational_function& b) {
  return {a.numerator_ * b.numerator_, a.denominator_ * b.denominator_};
}
rational_function operator/(const rational_function& a, const rational_function& b) {
  if (b.is_zero()) throw std::domain_error("simpson::verify::rational_function: division by zero");
  return {a.numerator_ * b.denominator_, a.denominator_ * b.numerator_};
}
rational_function& rational_function::operator+=(const rational_function& b) { return *this = *this + b; }
rational_function& rational_function::operator-=(const rational_function& b) { return *this = *this - b; }
rational_function& rational_function::operator*=(const rational_function& b) { return *this = *this * b; }
rational_function& rational_function::operator/=(const rational_function& b) { return *this = *this / b; }

bool operator==(const rational_function& a, const rational_function& b) { return (a - b).is_zero(); }
bool operator!=(const rational_function& a, const rational_function& b) { return !(a == b); }

void rational_function::fold_constant_denominator() {
  if (degree(denominator_) == 0 && denominator_[0] != 1) {
    numerator_ /= denominator_[0];
    denominator_ = one();
  }
}

std::vector<std::pair<long, rational>> laurent_coefficients(const rational_function& f, long up_to) {
  const polynomial& d = f.denominator();
  const long shift = degree(d);
  for (long k = 0; k < shift; ++k) {
    if (d[static_cast<std::size_t>(k)] != 0) {
      throw std::invalid_argument("laurent_coefficients: denominator is not a monomial");
    }
  }
  const rational scale = d[static_cast<std::size_t>(shift)];
  std::vector<std::pair<long, rational>> out;
  const polynomial& n = f.numerator();
  for (long k = 0; k <= degree(n); ++k) {
    const long power = k - shift;
    if (power >= up_to) break;
    const rational c = n[static_cast<std::size_t>(k)];
    if (c != 0) out.emplace_back(power, c / scale);
  }
  return out;
}

}  // namespace simpson::verify
