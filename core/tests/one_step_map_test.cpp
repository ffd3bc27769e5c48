#include <simpson/one_step_map.hpp>

#include <simpson/precision.hpp>

#include <gtest/gtest.h>

namespace simpson {
namespace {

using R = rational;

TEST(OneStepMap, ApplyIsTheMatrixVectorProduct) {
  const one_step_matrix<R> phi{R(1, 2), R(-3), R(2, 5), R(7)};
  const phase_point<R> y = (phi * phase_point<R>{R(4), R(-1, 3)});
  EXPECT_EQ(y.p, R(1, 2) * 4 + R(-3) * R(-1, 3));  // 3
  EXPECT_EQ(y.q, R(2, 5) * 4 + R(7) * R(-1, 3));   // 8/5 − 7/3
  EXPECT_EQ(y.p, R(3));
  EXPECT_EQ(y.q, R(-11, 15));
}

TEST(OneStepMap, DeterminantIsAlphaDeltaMinusBetaGamma) {
  EXPECT_EQ(determinant(one_step_matrix<R>{R(1, 2), R(-3), R(2, 5), R(7)}), R(7, 2) + R(6, 5));
  EXPECT_EQ(determinant(one_step_matrix<R>{R(0), R(-1), R(1), R(0)}), R(1));
}

TEST(OneStepMap, SymplecticFormDefectVanishesExactlyForUnitDeterminant) {
  for (const auto& e : symplectic_form_defect(one_step_matrix<R>{R(2), R(3), R(1), R(2)})) EXPECT_EQ(e, R(0));  // det 1
  // det 2: the products give (Φᵀ J Φ)₁₂ = det Φ = 2, so the defect is ±1 off the diagonal.
  const auto defect = symplectic_form_defect(one_step_matrix<R>{R(2), R(3), R(0), R(1)});
  EXPECT_EQ(defect[0], R(0));
  EXPECT_EQ(defect[1], R(1));
  EXPECT_EQ(defect[2], R(-1));
  EXPECT_EQ(defect[3], R(0));
}

TEST(OneStepMap, ProductComposesMapsAndMultipliesDeterminants) {
  const one_step_matrix<R> a{R(1, 2), R(-3), R(2, 5), R(7)};
  const one_step_matrix<R> b{R(-1), R(4, 3), R(5), R(1, 7)};
  const phase_point<R> y{R(2, 9), R(-5)};
  const phase_point<R> via_product = (a * b) * y;
  const phase_point<R> one_by_one = a * (b * y);
  EXPECT_EQ(via_product.p, one_by_one.p);
  EXPECT_EQ(via_product.q, one_by_one.q);
  EXPECT_EQ(determinant(a * b), determinant(a) * determinant(b));
}

}  // namespace
}  // namespace simpson
