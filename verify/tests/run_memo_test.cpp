// What a run computes once (run_memo.hpp): a key computed once per memo, never shared between two
// memos (two runs in one process), and a key read as another type is another value.
#include <simpson/verify/run_memo.hpp>

#include <gtest/gtest.h>

#include <string>

namespace simpson::verify {
namespace {

TEST(RunMemo, AKeyIsComputedOncePerRun) {
  run_memo memo;
  int computed = 0;
  const auto compute = [&] { return ++computed * 10; };
  EXPECT_EQ(memo.remember<int>("table1", compute), 10);
  EXPECT_EQ(memo.remember<int>("table1", compute), 10);
  EXPECT_EQ(computed, 1);
  EXPECT_EQ(memo.remember<int>("another", compute), 20);
  EXPECT_EQ(computed, 2);
}

TEST(RunMemo, TwoRunsNeverShareAValue) {
  run_memo first, second;
  EXPECT_EQ(first.remember<std::string>("k", [] { return std::string("first run"); }), "first run");
  EXPECT_EQ(second.remember<std::string>("k", [] { return std::string("second run"); }), "second run");
}

TEST(RunMemo, TheTypeIsPartOfTheKey) {
  run_memo memo;
  EXPECT_EQ(memo.remember<int>("k", [] { return 1; }), 1);
  EXPECT_EQ(memo.remember<long>("k", [] { return 2L; }), 2L);
}

TEST(RunMemo, WithoutAMemoEveryCallComputes) {
  int computed = 0;
  for (int k = 0; k < 3; ++k) remembered<int>(nullptr, "k", [&] { return ++computed; });
  EXPECT_EQ(computed, 3);
}

}  // namespace
}  // namespace simpson::verify
