// The steppers as straight-line programs (rounded_program.hpp): each program, evaluated in the
// stepper's format, agrees bit for bit with the stepper on random states; a program with one
// operation reordered does not; in exact rationals each program is the scheme's exact map.

#include <simpson/rounded_program.hpp>

#include <simpson/newmark_map.hpp>
#include <simpson/precision.hpp>
#include <simpson/shear_form.hpp>
#include <simpson/simpson_map.hpp>
#include <simpson/verinum_leapfrog.hpp>

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <algorithm>
#include <functional>
#include <random>

namespace simpson {
namespace {

/// The bits of a float or a double.
template <class Real>
auto bits_of(Real x) {
  using word = std::conditional_t<sizeof(Real) == 4, std::uint32_t, std::uint64_t>;
  word w;
  std::memcpy(&w, &x, sizeof w);
  return w;
}

/// How many of `samples` random states in [-1, 1]² (fixed seed) give a program result that differs
/// in some bit from the stepper's.
template <class Real>
int differing_states(const rounded_program& program, const std::map<std::string, Real>& coefficients,
                     const std::function<phase_point<Real>(const phase_point<Real>&)>& stepper, int samples = 20000) {
  std::mt19937_64 g(20231025);
  std::uniform_real_distribution<Real> u(-1, 1);
  int differing = 0;
  for (int k = 0; k < samples; ++k) {
    const phase_point<Real> y{u(g), u(g)};
    const phase_point<Real> modelled = evaluate(program, coefficients, y), executed = stepper(y);
    if (bits_of(modelled.p) != bits_of(executed.p) || bits_of(modelled.q) != bits_of(executed.q)) ++differing;
  }
  return differing;
}

template <class Real>
class RoundedProgram : public ::testing::Test {};
using formats = ::testing::Types<float, double>;
struct format_names {
  template <class Real>
  static std::string GetName(int) {
    return sizeof(Real) == 4 ? "float" : "double";
  }
};
TYPED_TEST_SUITE(RoundedProgram, formats, format_names);

TYPED_TEST(RoundedProgram, EachProgramIsItsStepperBitForBit) {
  using Real = TypeParam;
  const oscillator_parameters<Real> par{Real(1), Real(1), Real(1) / 10};
  for (const one_step_matrix<Real>& phi : {simpson_map(par), newmark_map(par)}) {
    EXPECT_EQ(differing_states<Real>(matrix_program("matrix"), matrix_coefficients(phi), [&](const phase_point<Real>& y) { return phi * y; }), 0);
  }
  const shear_coefficients<Real> s = simpson_shear_coefficients(par);
  EXPECT_EQ(differing_states<Real>(shear_program(), {{"c", s.drift}, {"b", s.kick}},
                                   [&](const phase_point<Real>& y) { return shear_step(s, y); }),
            0);
  const Real h = Real(1) / 32;
  EXPECT_EQ(differing_states<Real>(verinum_leapfrog_program(), {{"h", h}, {"half", Real(0.5)}},
                                   [&](const phase_point<Real>& y) { return verinum_leapfrog_step(h, y); }),
            0);
}

TYPED_TEST(RoundedProgram, AProgramWithOneOperationReorderedIsCaught) {
  using Real = TypeParam;
  const oscillator_parameters<Real> par{Real(1), Real(1), Real(1) / 10};
  // Leapfrog's position update associated the other way: q + (h p + c a).
  rounded_program leapfrog = verinum_leapfrog_program();
  leapfrog.body = {{"a", rounded_op::neg, "q", ""},       {"hp", rounded_op::mul, "h", "p"},     {"hh", rounded_op::mul, "h", "h"},
                   {"c", rounded_op::mul, "half", "hh"},  {"ca", rounded_op::mul, "c", "a"},     {"t", rounded_op::add, "hp", "ca"},
                   {"q1", rounded_op::add, "q", "t"},     {"a1", rounded_op::neg, "q1", ""},     {"s2", rounded_op::add, "a", "a1"},
                   {"d", rounded_op::mul, "half", "h"},   {"ds", rounded_op::mul, "d", "s2"},    {"p1", rounded_op::add, "p", "ds"}};
  const Real h = Real(1) / 32;
  EXPECT_GT(differing_states<Real>(leapfrog, {{"h", h}, {"half", Real(0.5)}},
                                   [&](const phase_point<Real>& y) { return verinum_leapfrog_step(h, y); }),
            0);
  // The shear form with its updates reordered: the kick first (p += b q, q += c p, q += c p).
  rounded_program shear = shear_program();
  shear.body = {{"bq", rounded_op::mul, "b", "q"},   {"p1", rounded_op::add, "p", "bq"},  {"cp", rounded_op::mul, "c", "p1"},
                {"q1", rounded_op::add, "q", "cp"},  {"cp1", rounded_op::mul, "c", "p1"}, {"q2", rounded_op::add, "q1", "cp1"}};
  const shear_coefficients<Real> s = simpson_shear_coefficients(par);
  EXPECT_GT(differing_states<Real>(shear, {{"c", s.drift}, {"b", s.kick}}, [&](const phase_point<Real>& y) { return shear_step(s, y); }),
            0);
  // The matrix form with p' computed from the new q'.
  rounded_program matrix = matrix_program("matrix");
  std::rotate(matrix.body.begin(), matrix.body.begin() + 3, matrix.body.end());
  matrix.body[3].right = "q1";
  const one_step_matrix<Real> phi = simpson_map(par);
  EXPECT_GT(differing_states<Real>(matrix, matrix_coefficients(phi), [&](const phase_point<Real>& y) { return phi * y; }), 0);
}

TEST(RoundedProgramExact, InRationalsEachProgramIsItsSchemesExactMap) {
  const oscillator_parameters<rational> par{rational(1), rational(1), rational(1, 10)};
  const one_step_matrix<rational> phi = simpson_map(par);
  const shear_coefficients<rational> s = simpson_shear_coefficients(par);
  const one_step_matrix<rational> shear = matrix_of<rational>(shear_program(), {{"c", s.drift}, {"b", s.kick}});
  EXPECT_TRUE(shear.alpha == phi.alpha && shear.beta == phi.beta && shear.gamma == phi.gamma && shear.delta == phi.delta);
  // Leapfrog (velocity Verlet, m = ω = 1): ((1 − h²/2, −h(1 − h²/4)), (h, 1 − h²/2)).
  const rational h(1, 32);
  const one_step_matrix<rational> leapfrog = matrix_of<rational>(verinum_leapfrog_program(), {{"h", h}, {"half", rational(1, 2)}});
  EXPECT_EQ(leapfrog.alpha, 1 - h * h / 2);
  EXPECT_EQ(leapfrog.beta, -h * (1 - h * h / 4));
  EXPECT_EQ(leapfrog.gamma, h);
  EXPECT_EQ(leapfrog.delta, 1 - h * h / 2);
  EXPECT_EQ(determinant(leapfrog), 1);
}

}  // namespace
}  // namespace simpson
