// Trace files: the CSV forms, Pupil's export, JSON, bad input, interpolation.
#include "foveate/gaze/trace.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "foveate/core/error.hpp"

namespace foveate::gaze {
namespace {

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(TraceCsv, SecondsNormalizedWithOptionalColumns) {
  const Trace t = parse_trace_csv(
      "# a comment\ntime_s,x,y,confidence,valid\n10.0,0.1,0.2,0.9,1\n10.5,0.3,0.4,,0\n", "a.csv");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_EQ(t.format, "csv");
  EXPECT_DOUBLE_EQ(t.time_origin_s, 10.0);
  EXPECT_DOUBLE_EQ(t.samples[0].time_s, 0.0);  // rebased to the first sample
  EXPECT_DOUBLE_EQ(t.samples[1].time_s, 0.5);
  EXPECT_DOUBLE_EQ(t.samples[0].pos.y, 0.2);
  EXPECT_DOUBLE_EQ(t.samples[0].confidence, 0.9);
  EXPECT_DOUBLE_EQ(t.samples[1].confidence, 1.0);  // empty: default
  EXPECT_FALSE(t.samples[1].valid);
  EXPECT_TRUE(t.latency_ms.empty());
}

TEST(TraceCsv, MillisecondsAndPixelsFromTheHeader) {
  const Trace t = parse_trace_csv(
      "# screen_px: 800x600\ntime_ms,x_px,y_px\n1000,400,150\n1016,200,600\n", "b.csv");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_NEAR(t.samples[1].time_s, 0.016, 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[0].pos.x, 0.5);
  EXPECT_DOUBLE_EQ(t.samples[0].pos.y, 0.25);
  EXPECT_DOUBLE_EQ(t.samples[1].pos.y, 1.0);
}

TEST(TraceCsv, UnitsFromOptionsWhenTheHeaderDoesNotSay) {
  TraceOptions o;
  o.time_unit = TimeUnit::kMilliseconds;
  o.pos_unit = PosUnit::kPixels;
  o.width_px = 1000;
  o.height_px = 500;
  const Trace t = parse_trace_csv("t,x,y\n0,100,100\n8,200,250\n", "c.csv", o);
  EXPECT_NEAR(t.samples[1].time_s, 0.008, 1e-12);
  EXPECT_DOUBLE_EQ(t.samples[1].pos.x, 0.2);
  EXPECT_DOUBLE_EQ(t.samples[1].pos.y, 0.5);
  // The header and the options disagree: an error, not a guess.
  EXPECT_NE(error_of([&] {
              parse_trace_csv("time_s,x,y\n0,1,1\n", "d.csv", o);
            }).find("the header gives time in s but the options say ms"),
            std::string::npos);
}

TEST(TraceCsv, PupilExportFlipsYAndIgnoresOtherColumns) {
  const std::string text =
      "gaze_timestamp,world_index,confidence,norm_pos_x,norm_pos_y,base_data,gaze_point_3d_x\n"
      "5123.25,0,0.95,0.25,0.1,\"5123.2-0 5123.3-1\",1.5\n"
      "5123.2583,1,0.4,0.5,0.5,\"5123.25-0\",\n";
  const Trace t = parse_trace_csv(text, "gaze_positions.csv");
  EXPECT_EQ(t.format, "pupil-csv");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(t.time_origin_s, 5123.25);
  EXPECT_NEAR(t.samples[1].time_s, 0.0083, 1e-9);
  EXPECT_DOUBLE_EQ(t.samples[0].pos.y, 0.9);
  EXPECT_DOUBLE_EQ(t.samples[0].confidence, 0.95);
  EXPECT_DOUBLE_EQ(t.samples[1].confidence, 0.4);
}

TEST(TraceCsv, BadSamplesAreDroppedAndCounted) {
  const Trace t = parse_trace_csv(
      "time_s,x,y,confidence\n"
      "0.00,0.5,0.5,1\n"
      "0.01,nan,0.5,1\n"  // non-finite
      "0.02,0.5,inf,1\n"  // non-finite
      "0.03,,0.5,1\n"     // missing value: non-finite
      "0.04,3.0,0.5,1\n"  // off screen
      "0.05,0.5,0.5,2\n"  // confidence > 1
      "0.06,0.6,0.5,1\n"
      "0.06,0.7,0.5,1\n"  // duplicate time
      "0.03,0.7,0.5,1\n"  // backwards
      "0.07,0.7,0.5,1\n",
      "bad.csv");
  ASSERT_EQ(t.samples.size(), 3u);
  EXPECT_EQ(t.dropped.non_finite, 3u);
  EXPECT_EQ(t.dropped.out_of_range, 2u);
  EXPECT_EQ(t.dropped.duplicate, 1u);
  EXPECT_EQ(t.dropped.backwards, 1u);
  EXPECT_DOUBLE_EQ(t.samples[1].pos.x, 0.6);
  EXPECT_DOUBLE_EQ(t.samples[2].pos.x, 0.7);
}

TEST(TraceCsv, SyntaxErrorsNameFileAndLine) {
  // A row that cannot be read: with strict, an error naming FILE:LINE.
  TraceOptions strict;
  strict.strict = true;
  auto strict_error = [&](const std::string& text) {
    return error_of([&] { parse_trace_csv(text, "f.csv", strict); });
  };
  EXPECT_EQ(strict_error("time_s,x,y\n0,0.5,0.5\n0.1,abc,0.5\n"),
            "f.csv:3: x: 'abc' is not a number; rejected by --strict");
  EXPECT_EQ(strict_error("time_s,x,y\n\n0,0.5\n"),
            "f.csv:3: expected 3 fields as in the header (line 1), got 2; rejected by --strict");
  EXPECT_EQ(strict_error("time_s,x,y,valid\n0,0.5,0.5,maybe\n"),
            "f.csv:2: valid: expected 1/0 or true/false, got 'maybe'; rejected by --strict");
  EXPECT_EQ(strict_error("time_s,x,y\n0,\"0.5,0.5\n"),
            "f.csv:2: unterminated quoted field; rejected by --strict");
  EXPECT_EQ(strict_error("time_s,x,y\n0,0.5,0.5\n0.1,0.5"),
            "f.csv:3: expected 3 fields as in the header (line 1), got 2 (the last line is cut "
            "off: no newline at its end); rejected by --strict");
  EXPECT_NE(error_of([] {
              parse_trace_csv("a,b,c\n1,2,3\n", "f.csv");
            }).find("f.csv:1: the header needs"),
            std::string::npos);
  EXPECT_EQ(error_of([] { parse_trace_csv("", "f.csv"); }),
            "f.csv: empty file: expected a header line and samples");
  EXPECT_NE(error_of([] {
              parse_trace_csv("# screen_px: big\ntime_s,x,y\n", "f.csv");
            }).find("f.csv:1: screen_px"),
            std::string::npos);
  // Only bad samples: an error that says why, with a hint for pixel files.
  EXPECT_EQ(error_of([] { parse_trace_csv("time_s,x,y\n0,960,540\n1,100,100\n", "f.csv"); }),
            "f.csv: no usable gaze sample (2 dropped (2 out-of-range)); if the positions are "
            "pixels, name the columns x_px,y_px or choose pixel units");
}

TEST(TraceCsv, UnreadableRowsAreSkippedAndNamed) {
  // Without strict the row is skipped, the rest read, and the line named.
  const Trace t =
      parse_trace_csv("time_s,x,y\n0,0.5,0.5\n0.1,abc,0.5\n0.2,0.5,0.5\n0.3,0.5", "f.csv");
  EXPECT_EQ(t.samples.size(), 2u);
  EXPECT_EQ(t.skipped_rows, 2u);
  ASSERT_EQ(t.warnings.size(), 2u);
  EXPECT_EQ(t.warnings[0], "f.csv:3: x: 'abc' is not a number; row skipped");
  EXPECT_EQ(t.warnings[1],
            "f.csv:5: expected 3 fields as in the header (line 1), got 2 (the last line is cut "
            "off: no newline at its end); row skipped");
  // The source's summary after the run counts them too.
  EXPECT_EQ(TraceSource(t, "f.csv").report(),
            "trace f.csv: none dropped, 2 unreadable rows skipped");
  // A complete last line without a newline is read.
  EXPECT_EQ(parse_trace_csv("time_s,x,y\n0,0.5,0.5\n0.1,0.5,0.5", "f.csv").samples.size(), 2u);
  // Nothing readable at all: the error names the first row.
  EXPECT_EQ(error_of([] { parse_trace_csv("time_s,x,y\n0,0.5\n", "f.csv"); }),
            "f.csv: no usable gaze sample (none dropped; 1 row(s) could not be read, the first: "
            "f.csv:2: expected 3 fields as in the header (line 1), got 2; row skipped)");
}

TEST(TraceJson, ArrayAndObjectSamples) {
  const Trace a = parse_trace_json(
      R"({"format": "foveate-gaze", "time_unit": "ms", "position_unit": "px",
          "screen_px": [200, 100], "samples": [[0, 50, 50, 0.8], [10, 100, 25, 1, false]]})",
      "a.json");
  ASSERT_EQ(a.samples.size(), 2u);
  EXPECT_DOUBLE_EQ(a.samples[0].pos.x, 0.25);
  EXPECT_DOUBLE_EQ(a.samples[0].pos.y, 0.5);
  EXPECT_DOUBLE_EQ(a.samples[0].confidence, 0.8);
  EXPECT_NEAR(a.samples[1].time_s, 0.01, 1e-12);
  EXPECT_FALSE(a.samples[1].valid);
  const Trace b = parse_trace_json(
      R"([{"t": 1.0, "x": 0.1, "y": 0.2}, {"t": 1.5, "x": null, "y": 0.2},
          {"t": 2.0, "x": 0.3, "y": 0.4, "confidence": 0.5, "valid": true}])",
      "b.json");
  ASSERT_EQ(b.samples.size(), 2u);
  EXPECT_EQ(b.dropped.non_finite, 1u);  // null: a missing value
  EXPECT_DOUBLE_EQ(b.samples[1].time_s, 1.0);
  EXPECT_EQ(error_of([] { parse_trace_json(R"({"samples": [[0, 0.5]]})", "c.json"); }),
            "c.json: samples[0]: expected [t, x, y] or [t, x, y, confidence(, valid)]");
  EXPECT_NE(error_of([] {
              parse_trace_json(R"({"samples": [], "colour": 1})", "c.json");
            }).find("colour"),
            std::string::npos);
  EXPECT_NE(error_of([] {
              parse_trace_json(R"([{"t": 0, "x": "left", "y": 0}])", "c.json");
            }).find("samples[0].x: expected a number"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse_trace_json("{\"samples\": [", "c.json"); }).find("c.json"),
            std::string::npos);
}

TEST(TraceFiles, RoundTripThroughCsvAndJsonFiles) {
  Trace t;
  t.samples = {{0.0, {0.1, 0.2}, 1.0, true}, {0.25, {0.3, 0.4}, 0.5, false}};
  t.latency_ms = {12.5, 14.0};
  const auto dir = std::filesystem::temp_directory_path();
  const std::string csv = (dir / "foveate_gaze_rt.csv").string();
  const std::string json = (dir / "foveate_gaze_rt.json").string();
  std::ofstream(csv) << trace_to_csv(t);
  std::ofstream(json) << trace_to_json(t);
  for (const std::string& path : {csv, json}) {
    const Trace r = load_trace(path);
    ASSERT_EQ(r.samples.size(), 2u) << path;
    EXPECT_DOUBLE_EQ(r.samples[1].time_s, 0.25);
    EXPECT_DOUBLE_EQ(r.samples[1].pos.y, 0.4);
    EXPECT_DOUBLE_EQ(r.samples[1].confidence, 0.5);
    EXPECT_FALSE(r.samples[1].valid);
  }
  const Trace r = load_trace(csv);
  ASSERT_EQ(r.latency_ms.size(), 2u);
  EXPECT_DOUBLE_EQ(r.latency_ms[1], 14.0);
  std::filesystem::remove(csv);
  std::filesystem::remove(json);
}

TEST(TraceInterpolation, LinearBetweenSamplesHeldAtTheEnds) {
  Trace t;
  t.samples = {{0.0, {0.2, 0.4}, 1.0, true},
               {0.01, {0.4, 0.2}, 0.8, true},
               {0.02, {0.4, 0.2}, 1.0, false},  // a blink starts
               {0.20, {0.9, 0.9}, 1.0, true},   // after a 180 ms gap (a dropout)
               {0.21, {0.8, 0.9}, 1.0, true}};
  GazeSample s = interpolate(t, 0.0025);
  EXPECT_TRUE(s.valid);
  EXPECT_DOUBLE_EQ(s.time_s, 0.0025);
  EXPECT_NEAR(s.pos.x, 0.25, 1e-12);
  EXPECT_NEAR(s.pos.y, 0.35, 1e-12);
  EXPECT_NEAR(s.confidence, 0.95, 1e-12);
  s = interpolate(t, 0.015);  // towards an invalid sample: the last valid one
  EXPECT_TRUE(s.valid);
  EXPECT_DOUBLE_EQ(s.pos.x, 0.4);
  s = interpolate(t, 0.1);  // inside the gap
  EXPECT_FALSE(s.valid);
  s = interpolate(t, 0.205);
  EXPECT_NEAR(s.pos.x, 0.85, 1e-12);
  s = interpolate(t, -1.0);
  EXPECT_DOUBLE_EQ(s.pos.x, 0.2);
  s = interpolate(t, 5.0);
  EXPECT_DOUBLE_EQ(s.pos.x, 0.8);
  InterpolationOptions loop;
  loop.end = TraceEnd::kLoop;
  s = interpolate(t, 0.21 + 0.0025, loop);
  EXPECT_NEAR(s.pos.x, 0.25, 1e-9);
  TraceSource src(t, "t.csv");
  EXPECT_NEAR(src.sample(0.005).pos.x, 0.3, 1e-12);
  EXPECT_NE(src.describe().find("5 samples"), std::string::npos);
}

}  // namespace
}  // namespace foveate::gaze
