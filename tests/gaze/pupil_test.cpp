// The live Pupil protocol against a local publisher speaking the same
// protocol. Every wait is bounded; no assertion depends on how fast it is.
#include "foveate/gaze/pupil.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <functional>
#include <msgpack.hpp>
#include <thread>

#include "fake_pupil.hpp"
#include "foveate/core/error.hpp"

namespace foveate::gaze {
namespace {

using testing::FakePupil;

/// Calls `step` every 10 ms until `done` or `timeout_s`; returns done().
bool eventually(const std::function<bool()>& done, const std::function<void()>& step = {},
                double timeout_s = 4.0) {
  const auto until = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (std::chrono::steady_clock::now() < until) {
    if (done()) return true;
    if (step) step();
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return done();
}

PupilOptions options_for(const FakePupil& fake) {
  PupilOptions o;
  o.host = "127.0.0.1";
  o.port = fake.control_port();
  o.request_timeout_ms = 300;
  o.receive_timeout_ms = 20;
  o.silence_s = 0.3;
  o.max_message_bytes = 4096;
  return o;
}

std::string pack(const std::function<void(msgpack::packer<msgpack::sbuffer>&)>& f) {
  msgpack::sbuffer buf;
  msgpack::packer<msgpack::sbuffer> pk(&buf);
  f(pk);
  return {buf.data(), buf.size()};
}

TEST(PupilDecode, ReadsNormPosConfidenceTimestampAndFlipsY) {
  const auto g = decode_pupil_gaze(FakePupil::pack_gaze(0.25, 0.2, 0.9, 1234.5));
  ASSERT_TRUE(g);
  EXPECT_DOUBLE_EQ(g->pos.x, 0.25);
  EXPECT_DOUBLE_EQ(g->pos.y, 0.8);  // origin bottom-left -> top-left
  EXPECT_DOUBLE_EQ(g->confidence, 0.9);
  EXPECT_DOUBLE_EQ(g->timestamp, 1234.5);
  // Integers are numbers too.
  const auto i = decode_pupil_gaze(pack([](auto& pk) {
    pk.pack_map(3);
    pk.pack(std::string("norm_pos"));
    pk.pack_array(2);
    pk.pack(1);
    pk.pack(0);
    pk.pack(std::string("confidence"));
    pk.pack(1);
    pk.pack(std::string("timestamp"));
    pk.pack(-7);
  }));
  ASSERT_TRUE(i);
  EXPECT_EQ(i->pos.x, 1.0);
  EXPECT_EQ(i->pos.y, 1.0);
  EXPECT_EQ(i->timestamp, -7.0);
}

TEST(PupilDecode, RejectsMalformedAndHostileFramesWithoutThrowing) {
  const std::string good = FakePupil::pack_gaze(0.5, 0.5, 1.0, 1.0);
  EXPECT_FALSE(decode_pupil_gaze(""));
  EXPECT_FALSE(decode_pupil_gaze("not msgpack at all"));
  EXPECT_FALSE(decode_pupil_gaze(good.substr(0, good.size() - 3)));           // truncated
  EXPECT_FALSE(decode_pupil_gaze(good + "x"));                                // trailing bytes
  EXPECT_FALSE(decode_pupil_gaze(pack([](auto& pk) { pk.pack_array(0); })));  // not a map
  EXPECT_FALSE(decode_pupil_gaze(pack([](auto& pk) {                          // no timestamp
    pk.pack_map(2);
    pk.pack(std::string("norm_pos"));
    pk.pack_array(2);
    pk.pack(0.5);
    pk.pack(0.5);
    pk.pack(std::string("confidence"));
    pk.pack(1.0);
  })));
  EXPECT_FALSE(decode_pupil_gaze(pack([](auto& pk) {  // norm_pos of three
    pk.pack_map(3);
    pk.pack(std::string("norm_pos"));
    pk.pack_array(3);
    pk.pack(0.5);
    pk.pack(0.5);
    pk.pack(0.5);
    pk.pack(std::string("confidence"));
    pk.pack(1.0);
    pk.pack(std::string("timestamp"));
    pk.pack(1.0);
  })));
  EXPECT_FALSE(decode_pupil_gaze(pack([](auto& pk) {  // a string where a number goes
    pk.pack_map(3);
    pk.pack(std::string("norm_pos"));
    pk.pack_array(2);
    pk.pack(0.5);
    pk.pack(0.5);
    pk.pack(std::string("confidence"));
    pk.pack(std::string("high"));
    pk.pack(std::string("timestamp"));
    pk.pack(1.0);
  })));
  // Headers declaring 2^32-1 elements: refused by the limits, not allocated.
  EXPECT_FALSE(decode_pupil_gaze(std::string("\xdd\xff\xff\xff\xff", 5)));  // array32
  EXPECT_FALSE(decode_pupil_gaze(std::string("\xdf\xff\xff\xff\xff", 5)));  // map32
  EXPECT_FALSE(decode_pupil_gaze(std::string("\xdb\xff\xff\xff\xff", 5)));  // str32
  // Nesting deeper than the limit.
  EXPECT_FALSE(decode_pupil_gaze(std::string(64, '\x91') + "\x01"));
  // A string longer than the limit inside an otherwise good datum.
  EXPECT_FALSE(decode_pupil_gaze(pack([](auto& pk) {
    pk.pack_map(4);
    pk.pack(std::string("norm_pos"));
    pk.pack_array(2);
    pk.pack(0.5);
    pk.pack(0.5);
    pk.pack(std::string("confidence"));
    pk.pack(1.0);
    pk.pack(std::string("timestamp"));
    pk.pack(1.0);
    pk.pack(std::string("note"));
    pk.pack(std::string(10000, 'a'));
  })));
}

TEST(PupilAddress, ParsesHostAndPort) {
  EXPECT_EQ(parse_pupil_address("").port, 50020);
  EXPECT_EQ(parse_pupil_address("").host, "127.0.0.1");
  const PupilOptions o = parse_pupil_address("10.0.0.7:50021");
  EXPECT_EQ(o.host, "10.0.0.7");
  EXPECT_EQ(o.port, 50021);
  EXPECT_EQ(parse_pupil_address("tracker.local").host, "tracker.local");
  EXPECT_THROW(parse_pupil_address("host:0"), Error);
  EXPECT_THROW(parse_pupil_address("host:70000"), Error);
  EXPECT_THROW(parse_pupil_address("host:abc"), Error);
  EXPECT_THROW(parse_pupil_address(":50020"), Error);
}

TEST(PupilLive, ReceivesGazeWithTheClockOffsetApplied) {
  FakePupil fake(1000.0);  // the tracker's clock runs 1000 s ahead
  PupilSource src(options_for(fake));
  ASSERT_TRUE(src.wait_connected(4.0));
  ASSERT_TRUE(eventually([&] { return src.counters().accepted > 0; },
                         [&] { fake.publish_gaze(0.25, 0.2, 0.9, fake.clock()); }));
  const double t = 5.0;  // any render clock: times come back on it
  const GazeSample s = src.sample(t);
  EXPECT_TRUE(s.valid);
  EXPECT_DOUBLE_EQ(s.pos.x, 0.25);
  EXPECT_DOUBLE_EQ(s.pos.y, 0.8);
  EXPECT_DOUBLE_EQ(s.confidence, 0.9);
  // The sample was taken a moment ago, not 1000 s in the future.
  EXPECT_LE(s.time_s, t + 0.05);
  EXPECT_GT(s.time_s, t - 1.0);
  EXPECT_EQ(src.counters().connects, 1u);
  EXPECT_EQ(src.counters().malformed, 0u);
}

TEST(PupilLive, CountsMalformedOversizedAndBadSamplesAndKeepsGoing) {
  FakePupil fake(0.0);
  PupilOptions o = options_for(fake);
  o.queue_limit = 1000;
  PupilSource src(o);
  ASSERT_TRUE(src.wait_connected(4.0));
  ASSERT_TRUE(eventually([&] { return src.counters().accepted > 0; },
                         [&] { fake.publish_gaze(0.5, 0.5, 1.0, fake.clock()); }));
  const double ts = fake.clock() + 0.5;  // ahead of every sample so far
  fake.publish_gaze(0.1, 0.1, 1.0, ts);
  // Malformed: junk, not a map, a 3-part message, a hostile array header.
  fake.publish({"gaze.2d.0.", "junk"});
  fake.publish({"gaze.2d.0.", pack([](auto& pk) {
                  pk.pack_array(2);
                  pk.pack(1);
                  pk.pack(2);
                })});
  fake.publish({"gaze.2d.0.", FakePupil::pack_gaze(0.5, 0.5, 1.0, ts + 0.01), "extra"});
  fake.publish({"gaze.2d.0.", std::string("\xdd\xff\xff\xff\xff", 5)});
  // Bad samples: NaN, backwards, duplicate time, far off screen, confidence > 1.
  fake.publish_gaze(std::nan(""), 0.5, 1.0, ts + 0.02);
  fake.publish_gaze(0.5, 0.5, 1.0, ts - 0.2);
  fake.publish_gaze(0.6, 0.5, 1.0, ts);
  fake.publish_gaze(5.0, 0.5, 1.0, ts + 0.03);
  fake.publish_gaze(0.5, 0.5, 1.5, ts + 0.04);
  // A marker: once it is through, everything before it was delivered in order.
  fake.publish_gaze(0.7, 0.3, 1.0, ts + 0.05);
  ASSERT_TRUE(eventually([&] { return std::fabs(src.sample(0).pos.x - 0.7) < 1e-12; }));
  PupilCounters c = src.counters();
  EXPECT_EQ(c.malformed, 4u);
  EXPECT_EQ(c.dropped.non_finite, 1u);
  EXPECT_EQ(c.dropped.backwards, 1u);
  EXPECT_EQ(c.dropped.duplicate, 1u);
  EXPECT_EQ(c.dropped.out_of_range, 2u);
  const auto drained = src.drain();
  ASSERT_GE(drained.size(), 3u);
  EXPECT_DOUBLE_EQ(drained[drained.size() - 2].pos.x, 0.1);
  EXPECT_DOUBLE_EQ(drained.back().pos.y, 0.7);

  // An oversized frame (over ZMQ_MAXMSGSIZE): the connection is dropped by
  // ZMQ and re-established; gaze flows again afterwards.
  fake.publish({"gaze.2d.0.", std::string(100000, 'x')});
  EXPECT_TRUE(eventually([&] { return std::fabs(src.sample(0).pos.x - 0.35) < 1e-12; },
                         [&] { fake.publish_gaze(0.35, 0.5, 1.0, fake.clock()); }));
  EXPECT_EQ(src.counters().malformed, 4u);  // it never reached the decoder
}

TEST(PupilLive, ReconnectsWhenThePublisherDiesAndComesBack) {
  FakePupil fake(1000.0);
  PupilSource src(options_for(fake));
  ASSERT_TRUE(src.wait_connected(4.0));
  ASSERT_TRUE(eventually([&] { return src.counters().accepted > 0; },
                         [&] { fake.publish_gaze(0.2, 0.5, 1.0, fake.clock()); }));
  const int old_pub = fake.pub_port();
  fake.stop();
  // Silent for longer than silence_s: no longer connected; requests time out.
  EXPECT_TRUE(eventually([&] { return !src.counters().connected; }));
  EXPECT_TRUE(eventually([&] { return src.counters().failed_requests > 0; }));
  // Back on the same control port, a new publisher port and a restarted clock.
  fake.start(-500.0);
  EXPECT_NE(fake.pub_port(), old_pub);
  ASSERT_TRUE(eventually([&] { return std::fabs(src.sample(0).pos.x - 0.8) < 1e-12; },
                         [&] { fake.publish_gaze(0.8, 0.5, 1.0, fake.clock()); }, 6.0));
  const PupilCounters c = src.counters();
  EXPECT_GE(c.connects, 2u);
  EXPECT_TRUE(c.connected);
  // The new clock was picked up: the sample is recent on the render clock.
  const GazeSample s = src.sample(10.0);
  EXPECT_LE(s.time_s, 10.05);
  EXPECT_GT(s.time_s, 9.0);
}

TEST(PupilLive, NoTrackerMeansInvalidGazeAndABoundedShutdown) {
  PupilOptions o;
  o.port = testing::unused_port();
  o.request_timeout_ms = 200;
  const auto start = std::chrono::steady_clock::now();
  {
    PupilSource src(o);
    EXPECT_FALSE(src.wait_connected(0.5));
    const GazeSample s = src.sample(1.0);
    EXPECT_FALSE(s.valid);
    EXPECT_EQ(s.confidence, 0.0);
    EXPECT_TRUE(eventually([&] { return src.counters().failed_requests > 0; }, {}, 2.0));
    EXPECT_NE(src.report().find("not connected"), std::string::npos);
  }
  const double took =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  EXPECT_LT(took, 5.0);  // every request and receive has a timeout
}

TEST(PupilLive, AnInvalidSubPortAnswerIsNamedNotConnected) {
  FakePupil fake;
  fake.answer_sub_port_with("99999999");
  PupilOptions o;
  o.port = fake.control_port();
  o.request_timeout_ms = 200;
  PupilSource src(o);
  EXPECT_FALSE(src.wait_connected(0.5));
  ASSERT_TRUE(eventually([&] { return !src.counters().last_failure.empty(); }, {}, 2.0));
  EXPECT_EQ(src.counters().last_failure,
            "the answer to SUB_PORT, '99999999', is not a valid port (1..65535)");
  // A tracker that does not answer at all says so instead.
  PupilOptions silent;
  silent.port = testing::unused_port();
  silent.request_timeout_ms = 200;
  PupilSource none(silent);
  EXPECT_FALSE(none.wait_connected(0.5));
  ASSERT_TRUE(eventually([&] { return !none.counters().last_failure.empty(); }, {}, 2.0));
  EXPECT_EQ(none.counters().last_failure, "no answer to SUB_PORT");
}

}  // namespace
}  // namespace foveate::gaze
