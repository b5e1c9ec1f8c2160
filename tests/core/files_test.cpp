// Reading user files safely (issue 13): what is not a regular file is refused
// before it is opened (a FIFO would block the open forever), size limits name
// themselves, JSON numbers beyond a double name the key, integers too long
// for 64 bits are out of range, and the planner's grid is bounded.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "../support/errors.hpp"
#include "foveate/core/file.hpp"
#include "foveate/core/json_read.hpp"
#include "foveate/core/planner.hpp"

using namespace foveate;
using foveate::test::error_of;

namespace {

std::filesystem::path temp_dir() {
  auto d =
      std::filesystem::temp_directory_path() / ("foveate-files-test-" + std::to_string(::getpid()));
  std::filesystem::create_directories(d);
  return d;
}

}  // namespace

TEST(Files, NotRegularFilesAreRefusedBeforeOpening) {
  const auto dir = temp_dir();
  const std::string fifo = (dir / "fifo").string();
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // Would block forever in open() if it were opened for reading.
  EXPECT_EQ(error_of([&] { read_file(fifo, "gaze trace"); }),
            fifo + ": the gaze trace is a named pipe (FIFO), not a regular file");
  EXPECT_EQ(error_of([&] { require_regular_file(fifo, "display JSON"); }),
            fifo + ": the display JSON is a named pipe (FIFO), not a regular file");
  EXPECT_EQ(error_of([&] { read_file(dir.string(), "camera path"); }),
            dir.string() + ": the camera path is a directory, not a regular file");
  EXPECT_EQ(error_of([&] { read_file("/dev/null", "image"); }),
            "/dev/null: the image is a character device, not a regular file");
  EXPECT_NE(error_of([&] {
              read_file((dir / "missing").string(), "gaze trace");
            }).find("missing: cannot open the gaze trace: No such file"),
            std::string::npos);
  std::filesystem::remove_all(dir);
}

// A file written whole or not at all: into a directory's name it is refused
// before anything is written, and a file already there is replaced whole.
TEST(Files, AtomicWritesRefuseADirectoryAndReplaceAFile) {
  const auto dir = temp_dir();
  EXPECT_EQ(error_of([&] { write_file_atomic(dir.string(), "x"); }),
            dir.string() + ": is a directory; give a file name");
  const std::string path = (dir / "a.txt").string();
  write_file_atomic(path, "first, longer");
  write_file_atomic(path, "second");
  EXPECT_EQ(read_file(path, "text"), "second");
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir),
                          std::filesystem::directory_iterator()),
            1);  // no temporary left beside it
  std::filesystem::remove_all(dir);
}

TEST(Files, SizeLimitNamesTheLimitAndHowToRaiseIt) {
  const auto dir = temp_dir();
  const std::string path = (dir / "big.csv").string();
  std::ofstream(path) << std::string(3000, 'x');
  EXPECT_EQ(read_file(path, "gaze trace", 3000).size(), 3000u);
  const std::string e = error_of([&] { read_file(path, "gaze trace", 2048, "set X to raise it"); });
  EXPECT_EQ(e, path + ": the gaze trace is 0.0 MiB, over the limit of 0.0 MiB (set X to raise it)");
  std::filesystem::remove_all(dir);
  ::setenv("FOVEATE_TEST_LIMIT", "3", 1);
  EXPECT_EQ(limit_from_env_mib("FOVEATE_TEST_LIMIT", 7), 3u << 20);
  ::setenv("FOVEATE_TEST_LIMIT", "-1", 1);
  EXPECT_EQ(error_of([] { limit_from_env_mib("FOVEATE_TEST_LIMIT", 7); }),
            "FOVEATE_TEST_LIMIT: expected a size in MiB (1..1073741824), got '-1'");
  ::unsetenv("FOVEATE_TEST_LIMIT");
  EXPECT_EQ(limit_from_env_mib("FOVEATE_TEST_LIMIT", 7), 7u << 20);
}

TEST(Json, NumberBeyondADoubleNamesTheFileAndKey) {
  EXPECT_EQ(error_of([] { parse_json(R"({"a": {"b": [1, 2e999]}})", "f.json"); }),
            "f.json: the number 2e999 at byte 21 (key a.b[1]) is out of range (beyond the "
            "largest double, about 1.8e308)");
  EXPECT_EQ(error_of([] { parse_json("-1e999", "g.json"); }),
            "g.json: the number -1e999 at byte 6 is out of range (beyond the largest double, "
            "about 1.8e308)");
}

TEST(Json, LongIntegersAreOutOfRangeNotFractions) {
  int out = 0;
  auto read = [&](const char* text) {
    const nlohmann::json j = parse_json(text, "d");
    JsonReader r(j, "d");
    r.integer("n", out, 1, 100);
  };
  EXPECT_EQ(error_of([&] { read(R"({"n": 99999999999999999999})"); }),
            "d.n: 1e+20 is out of range [1, 100]");
  EXPECT_EQ(error_of([&] { read(R"({"n": 12345678901234567890})"); }),
            "d.n: 12345678901234567890 is out of range [1, 100]");
  EXPECT_EQ(error_of([&] { read(R"({"n": 2.5})"); }), "d.n: expected an integer, got a fraction");
  read(R"({"n": 1e1})");  // a whole number written with an exponent
  EXPECT_EQ(out, 10);
}

TEST(Planner, GridIsBoundedWithAnErrorNamingTheLimit) {
  PlannerOptions o;
  o.grid_step_deg = 1e-9;
  const Display d = Display::load("desktop-1080p");
  const std::string e = error_of([&] { plan_layers(d, AcuityModel::preset("A"), o); });
  EXPECT_NE(e.find("over the limit of 10000"), std::string::npos) << e;
  EXPECT_NE(e.find("use a step of at least 0.0024 deg"), std::string::npos) << e;
  // With a smaller limit (a fast test): the step it suggests is accepted, and
  // raising the limit accepts the finer one.
  o.max_grid_points = 1000;
  o.grid_step_deg = 0.02;
  const std::string small = error_of([&] { plan_layers(d, AcuityModel::preset("A"), o); });
  EXPECT_NE(small.find("1168 candidate radii"), std::string::npos) << small;
  EXPECT_NE(small.find("use a step of at least 0.024 deg"), std::string::npos) << small;
  o.grid_step_deg = 0.024;
  EXPECT_NO_THROW(plan_layers(d, AcuityModel::preset("A"), o));
  o.grid_step_deg = 0.02;
  o.max_grid_points = 2000;
  EXPECT_NO_THROW(plan_layers(d, AcuityModel::preset("A"), o));
}
