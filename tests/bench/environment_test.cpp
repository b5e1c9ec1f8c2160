#include "foveate/bench/environment.hpp"

#include <gtest/gtest.h>

using foveate::bench::busy_machine;
using foveate::bench::CpuSample;
using foveate::bench::others_cpu_share;
using foveate::bench::RunEnvironment;

// Two cores for 10 s: 20 s of CPU time in all. This process used 12 of the
// 18 busy seconds, so other processes took 6 of 20: 30 %.
TEST(Environment, OthersShareIsTheBusyTimeThisProcessDidNotUse) {
  const CpuSample a{100.0, 400.0, 5.0}, b{118.0, 420.0, 17.0};
  EXPECT_DOUBLE_EQ(others_cpu_share(a, b), 0.3);
  // This process alone: nothing for others (clamped where the clocks'
  // granularity puts its own time a tick above the machine's).
  EXPECT_DOUBLE_EQ(others_cpu_share(a, {110.0, 420.0, 15.5}), 0.0);
  // Unknown or empty intervals say so rather than guess.
  EXPECT_EQ(others_cpu_share({-1, -1, 5.0}, b), -1.0);
  EXPECT_EQ(others_cpu_share(a, a), -1.0);
  // 1.5 s on 2 cores: a few 10 ms ticks would move the share too far.
  EXPECT_EQ(others_cpu_share(a, {102.9, 403.0, 5.9}), -1.0);
}

TEST(Environment, SamplesThisMachinesClock) {
  const CpuSample a = foveate::bench::sample_cpu();
  ASSERT_GE(a.total_s, 0.0) << "/proc/stat unreadable";
  EXPECT_GE(a.own_s, 0.0);
  EXPECT_GE(a.total_s, a.busy_s);
}

// Other work sharing the CPU inflated a published table four- to six-fold
// (docs/performance.md): a run measured while other processes took a fifth
// of the CPU or more says so; one on a quiet machine, or whose share is
// unknown, says nothing.
TEST(Environment, SaysWhenOtherWorkSharedTheCpu) {
  RunEnvironment e;
  e.cores = 2;
  e.load_start = {14.2, 9.0, 4.0};
  e.others_cpu_share = 0.83;
  const auto busy = busy_machine(e);
  ASSERT_TRUE(busy.has_value());
  EXPECT_NE(busy->find("other processes used 83 %"), std::string::npos) << *busy;
  EXPECT_NE(busy->find("load average 14.2"), std::string::npos) << *busy;
  EXPECT_NE(busy->find("within this run"), std::string::npos) << *busy;
  e.others_cpu_share = 0.2;
  EXPECT_TRUE(busy_machine(e).has_value());
  e.others_cpu_share = 0.19;
  EXPECT_FALSE(busy_machine(e).has_value());
  e.others_cpu_share = -1;
  EXPECT_FALSE(busy_machine(e).has_value());
}
