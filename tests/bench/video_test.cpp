// The video writer as a library: frames in, a file out only when finished,
// nothing left behind otherwise; the pictures a video shows.
#include "foveate/bench/video.hpp"

#include <gtest/gtest.h>

#include <filesystem>

#include "errors.hpp"

using namespace foveate;
using foveate::test::error_of;
using namespace foveate::bench;
namespace fs = std::filesystem;

namespace {

fs::path fresh_dir(const std::string& name) {
  const fs::path dir = fs::temp_directory_path() / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

Image flat(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  Image img(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.at(x, y);
      p[0] = r, p[1] = g, p[2] = b, p[3] = 255;
    }
  }
  return img;
}

size_t entries(const fs::path& dir) {
  return static_cast<size_t>(std::distance(fs::directory_iterator(dir), fs::directory_iterator()));
}

}  // namespace

TEST(Video, TheFileAppearsOnlyWhenFinished) {
  if (!VideoWriter::available()) GTEST_SKIP() << "built without libavcodec";
  const fs::path dir = fresh_dir("foveate-video-finish");
  const std::string path = (dir / "clip.mp4").string();
  {
    VideoWriter v(path, 33, 17, 30.0);
    EXPECT_EQ(v.encoder(), "libx264");  // Debian's libavcodec has it
    EXPECT_EQ(v.padded_width(), 34);
    EXPECT_EQ(v.padded_height(), 18);
    EXPECT_TRUE(v.padded());
    for (int k = 0; k < 3; ++k) v.write(flat(33, 17, 200, 40, 10));
    EXPECT_FALSE(fs::exists(path));  // still the temporary file
    EXPECT_EQ(entries(dir), 1u);
    v.finish();
    EXPECT_EQ(v.frames(), 3);
  }
  EXPECT_GT(fs::file_size(path), 0u);
  EXPECT_EQ(entries(dir), 1u);  // the temporary file became the video
  fs::remove_all(dir);
}

TEST(Video, AnAbandonedVideoLeavesNothing) {
  if (!VideoWriter::available()) GTEST_SKIP() << "built without libavcodec";
  const fs::path dir = fresh_dir("foveate-video-abandon");
  const std::string path = (dir / "clip.mkv").string();
  {
    VideoWriter v(path, 16, 16, 60.0);
    v.write(flat(16, 16, 0, 0, 0));
    EXPECT_NE(
        error_of([&] { v.write(flat(8, 16, 0, 0, 0)); }).find("frame of 8x16 in a video of 16x16"),
        std::string::npos);
  }  // destroyed without finish(), as when an exception unwinds
  EXPECT_EQ(entries(dir), 0u);
  {
    VideoWriter v(path, 16, 16, 60.0);
    EXPECT_NE(error_of([&] { v.finish(); }).find("no frames"), std::string::npos);
  }
  EXPECT_EQ(entries(dir), 0u);
  fs::remove_all(dir);
}

TEST(Video, FallsBackToTheNextEncoder) {
  if (!VideoWriter::available()) GTEST_SKIP() << "built without libavcodec";
  const fs::path dir = fresh_dir("foveate-video-fallback");
  const std::string path = (dir / "clip.mp4").string();
  VideoWriter v(path, 16, 16, 25.0, {"no-such-encoder", "mpeg4"});
  EXPECT_EQ(v.encoder(), "mpeg4");
  v.write(flat(16, 16, 10, 20, 30));
  v.finish();
  EXPECT_GT(fs::file_size(path), 0u);
  EXPECT_NE(video_summary(v, 25.0).find("mpeg4 (no H.264 encoder"), std::string::npos);
  const std::string err =
      error_of([&] { VideoWriter w((dir / "x.mp4").string(), 16, 16, 25.0, {"no-such-encoder"}); });
  EXPECT_NE(err.find("x.mp4: no usable video encoder (tried no-such-encoder (absent))"),
            std::string::npos)
      << err;
  EXPECT_FALSE(fs::exists(dir / "x.mp4"));
  EXPECT_EQ(entries(dir), 1u);  // clip.mp4 only: no temporary file of the failed one
  fs::remove_all(dir);
}

TEST(Video, BadPathsAndValuesNameTheFile) {
  if (!VideoWriter::available()) GTEST_SKIP() << "built without libavcodec";
  const fs::path dir = fresh_dir("foveate-video-bad");
  EXPECT_NE(error_of([&] {
              VideoWriter v((dir / "x.what").string(), 8, 8, 30);
            }).find("x.what: cannot tell the video container"),
            std::string::npos);
  EXPECT_NE(error_of([&] { VideoWriter v(dir.string(), 8, 8, 30); }).find("is a directory"),
            std::string::npos);
  EXPECT_NE(error_of([&] { VideoWriter v((dir / "x.mp4").string(), 8, 8, 0); }).find("frame rate"),
            std::string::npos);
  EXPECT_NE(error_of([&] { VideoWriter v((dir / "x.mp4").string(), 0, 8, 30); }).find("size"),
            std::string::npos);
  EXPECT_EQ(entries(dir), 0u);
  fs::remove_all(dir);
}

TEST(Video, TilesAndTheGazeMark) {
  const Image a = flat(4, 2, 255, 0, 0), b = flat(4, 2, 0, 255, 0), c = flat(4, 2, 0, 0, 255);
  const Image two = tile({&a, &b});
  ASSERT_EQ(two.width, 8);
  ASSERT_EQ(two.height, 2);
  EXPECT_EQ(two.at(3, 1)[0], 255);
  EXPECT_EQ(two.at(4, 0)[1], 255);
  // Four images: two rows of two; five: two rows of three, the last cell black.
  EXPECT_EQ(tile({&a, &b, &c, &a}).width, 8);
  EXPECT_EQ(tile({&a, &b, &c, &a}).height, 4);
  const Image five = tile({&a, &b, &c, &a, &b});
  ASSERT_EQ(five.width, 12);
  ASSERT_EQ(five.height, 4);
  EXPECT_EQ(five.at(10, 3)[0] + five.at(10, 3)[1] + five.at(10, 3)[2], 0);
  EXPECT_EQ(five.at(10, 3)[3], 255);
  EXPECT_NE(error_of([&] { (void)tile({&a, &two}); }).find("different sizes"), std::string::npos);

  Image img = flat(64, 64, 0, 0, 128);
  mark_gaze(img, {32, 32});
  // Radius max(6, 64 / 24) = 6: white on the ring, magenta at the centre,
  // untouched far away.
  EXPECT_EQ(img.at(38, 31)[0], 255);
  EXPECT_EQ(img.at(38, 31)[1], 255);
  EXPECT_EQ(img.at(32, 32)[0], 255);
  EXPECT_EQ(img.at(32, 32)[1], 77);
  EXPECT_EQ(img.at(5, 5)[2], 128);
  EXPECT_EQ(img.at(5, 5)[0], 0);
  mark_gaze(img, {-100, 1000});  // off the image: nothing drawn, nothing touched out of bounds
}
