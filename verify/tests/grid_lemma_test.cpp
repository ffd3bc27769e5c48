// The grid lemma with its premise computed (verify/ledger/src/grid_lemma.hpp): a difference that
// vanishes on the grid proves nothing unless GiNaC finds it a polynomial of the stated degree in
// each grid variable. Each case below vanishes on its grid; the old lemma, whose premise was a
// comment, "proved" every one of them.

#include "claim_support.hpp"

#include <gtest/gtest.h>

namespace simpson::verify::detail {
namespace {

TEST(GridLemma, ProvesAnIdentityAndRecordsTheDegreesItFound) {
  const proof p = prove_zero_on_grid("(a + b)^2 - a^2 - 2ab - b^2, times theta", {"a", "b"}, 2, [](const auto& v) {
    using S = std::decay_t<decltype(v[0])>;
    const S theta = theta_variable<S>();
    return S(theta * ((v[0] + v[1]) * (v[0] + v[1]) - v[0] * v[0] - 2 * v[0] * v[1] - v[1] * v[1]));
  });
  EXPECT_TRUE(p.proved) << p.evidence.dump();
  EXPECT_EQ(p.evidence["premise"], "holds (GiNaC): every difference is 0 in normal form");
}

// (x − 1)(x − 2) vanishes at x = 1, 2, the grid of degree 1: a false identity the premise stops.
TEST(GridLemma, ADifferenceOfHigherDegreeThanTheGridIsNotProved) {
  const proof p = prove_zero_on_grid("(x - 1)(x - 2) theta", {"x"}, 1, [](const auto& v) {
    using S = std::decay_t<decltype(v[0])>;
    return S((v[0] - 1) * (v[0] - 2) * theta_variable<S>());
  });
  EXPECT_FALSE(p.proved);
  EXPECT_EQ(p.evidence["premise"], "fails (GiNaC): degrees x 2 > 1");
}

// (x − 1)(x − 2)/x vanishes on the grid of degree 2 too, and is not a polynomial.
TEST(GridLemma, ADifferenceWithTheVariableInItsDenominatorIsNotProved) {
  const proof p = prove_zero_on_grid("(x - 1)(x - 2)/x", {"x", "y"}, std::vector<int>{2, 1}, [](const auto& v) {
    using S = std::decay_t<decltype(v[0])>;
    return std::vector<S>{S(v[1] - v[1]), S((v[0] - 1) * (v[0] - 2) * (v[0] - 3) / v[0])};
  });
  EXPECT_FALSE(p.proved);
  EXPECT_NE(p.evidence["premise"].get<std::string>().find("x in its denominator"), std::string::npos) << p.evidence.dump();
}

// A derivative by exact differences is exact to degree 4: of x^5 it is wrong, and the premise run says so.
TEST(GridLemma, ADerivativeByDifferencesOfTooHighADegreeIsNotProved) {
  const auto derivative_gap = [](int power) {
    return [power](const auto& v) {
      using S = std::decay_t<decltype(v[0])>;
      const auto f = [power](const S& u) { return monomial_potential::power(u, power); };
      return S(exact_derivative(f, v[0]) - power * monomial_potential::power(v[0], power - 1));
    };
  };
  EXPECT_TRUE(prove_zero_on_grid("d/dx x^4", {"x"}, 3, derivative_gap(4)).proved);
  const proof fifth = prove_zero_on_grid("d/dx x^5", {"x"}, 4, derivative_gap(5));
  EXPECT_FALSE(fifth.proved);
  EXPECT_NE(fifth.evidence["premise"].get<std::string>().find("degree <= 4"), std::string::npos) << fifth.evidence.dump();
}

}  // namespace
}  // namespace simpson::verify::detail
