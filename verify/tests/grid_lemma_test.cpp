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
  EXPECT_EQ(p.evidence.at("premise"), "holds (GiNaC): every difference is 0");
}

// (x − 1)(x − 2) vanishes at x = 1, 2, the grid of degree 1: a false identity the premise stops.
TEST(GridLemma, ADifferenceOfHigherDegreeThanTheGridIsNotProved) {
  const proof p = prove_zero_on_grid("(x - 1)(x - 2) theta", {"x"}, 1, [](const auto& v) {
    using S = std::decay_t<decltype(v[0])>;
    return S((v[0] - 1) * (v[0] - 2) * theta_variable<S>());
  });
  EXPECT_FALSE(p.proved);
  EXPECT_EQ(p.evidence.at("premise"), "fails (GiNaC, normal form): degrees x 2 > 1");
}

// (x − 1)(x − 2)/x vanishes on the grid of degree 2 too, and is not a polynomial.
TEST(GridLemma, ADifferenceWithTheVariableInItsDenominatorIsNotProved) {
  const proof p = prove_zero_on_grid("(x - 1)(x - 2)/x", {"x", "y"}, std::vector<int>{2, 1}, [](const auto& v) {
    using S = std::decay_t<decltype(v[0])>;
    return std::vector<S>{S(v[1] - v[1]), S((v[0] - 1) * (v[0] - 2) * (v[0] - 3) / v[0])};
  });
  EXPECT_FALSE(p.proved);
  EXPECT_NE(p.evidence.at("premise").get<std::string>().find("x in its denominator"), std::string::npos) << p.evidence.dump();
}

// A derivative by exact differences is exact to degree 4. A difference that compares it with the
// same differences written out is zero everywhere, yet proves nothing of a derivative of x^5: the
// premise run says so. With x^4 the derivative is exact and the identity with 4x^3 is proved.
TEST(GridLemma, ADerivativeByDifferencesOfTooHighADegreeIsNotProved) {
  const auto against_differences = [](int power) {
    return [power](const auto& v) {
      using S = std::decay_t<decltype(v[0])>;
      const auto f = [power](const S& u) { return monomial_potential::power(u, power); };
      const S by_hand = (4 * ((f(v[0] + 1) - f(v[0] - 1)) / 2) - (f(v[0] + 2) - f(v[0] - 2)) / 4) / 3;
      return S(exact_derivative(f, v[0]) - by_hand);
    };
  };
  const proof fifth = prove_zero_on_grid("d/dx x^5 against its differences", {"x"}, 4, against_differences(5));
  EXPECT_FALSE(fifth.proved);
  EXPECT_NE(fifth.evidence.at("premise").get<std::string>().find("degree <= 4"), std::string::npos) << fifth.evidence.dump();
  const proof fourth = prove_zero_on_grid("d/dx x^4 - 4x^3", {"x"}, 3, [](const auto& v) {
    using S = std::decay_t<decltype(v[0])>;
    const auto f = [](const S& u) { return monomial_potential::power(u, 4); };
    return S(exact_derivative(f, v[0]) - 4 * monomial_potential::power(v[0], 3));
  });
  EXPECT_TRUE(fourth.proved) << fourth.evidence.dump();
}

// A refuted difference needs no premise: the grid point that refutes it is named.
TEST(GridLemma, ARefutedDifferenceNeedsNoPremise) {
  const proof p = prove_zero_on_grid("x - 1", {"x"}, 1, [](const auto& v) {
    using S = std::decay_t<decltype(v[0])>;
    return S(v[0] - 1);
  });
  EXPECT_FALSE(p.proved);
  EXPECT_EQ(p.evidence.at("result"), "nonzero at x = 2: identity false");
  EXPECT_EQ(p.evidence.at("premise"), "not needed: the difference is not zero at a grid point");
}

}  // namespace
}  // namespace simpson::verify::detail
