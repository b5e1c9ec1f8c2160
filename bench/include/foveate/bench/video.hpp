#pragma once
// Video output through ffmpeg's libraries (libavcodec, libavformat,
// libswscale): frames (8-bit sRGB RGBA images) encoded as H.264 (libx264)
// when the build has that encoder, else the first of a short list of others,
// yuv420p, at a fixed frame rate, in the container the file name asks for
// (.mp4, .mkv, .mov, ...). The file is written to FILE.tmp-XXXXXX beside it
// and renamed when finish() succeeds; a writer destroyed before that (an
// error, an exception) removes the temporary file, so nothing half-written
// is ever left under the final name.
//
// Also the pictures a video shows: frames side by side and the gaze marked.
#include <memory>
#include <string>
#include <vector>

#include "foveate/core/display.hpp"
#include "foveate/core/image.hpp"

namespace foveate::bench {

class VideoWriter {
 public:
  /// Opens the temporary file and the encoder for frames of `width` x
  /// `height` at `fps` frames per second. Creates missing parent folders.
  /// Throws foveate::Error naming `path` when the container is unknown, the
  /// file cannot be written or no encoder is available. Odd sizes are padded
  /// to even ones (yuv420p needs them) by repeating the last column / row;
  /// padded_width() / padded_height() say what was encoded.
  /// `encoders`: libavcodec encoder names to try in order instead of the
  /// default libx264, libopenh264, mpeg4.
  VideoWriter(const std::string& path, int width, int height, double fps,
              const std::vector<std::string>& encoders = {});
  ~VideoWriter();
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  /// Encodes one frame; it must have the size given to the constructor.
  void write(const Image& frame);
  /// Flushes the encoder, writes the trailer, closes the file and renames it
  /// to its final name. Without frames written it throws (an empty video is
  /// not a video).
  void finish();

  /// The encoder used ("libx264", "mpeg4", ...).
  [[nodiscard]] const std::string& encoder() const;
  [[nodiscard]] int padded_width() const;
  [[nodiscard]] int padded_height() const;
  /// Whether the frames were padded (an odd width or height).
  [[nodiscard]] bool padded() const;
  [[nodiscard]] int frames() const;
  [[nodiscard]] const std::string& path() const;

  /// Whether this build can write videos at all (was built with libavcodec).
  static bool available();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Draws a gaze marker at `gaze_px` (pixels, origin top-left): a white ring
/// with a dark outline and a dark centre dot, sized with the image.
void mark_gaze(Image& image, Vec2d gaze_px);

/// Writes `name` into the bottom-left corner of a video's tile (white on a
/// dark box, scaled with the image), so that a side-by-side video says which
/// technique each tile shows.
void label_tile(Image& image, const std::string& name);

/// Images of equal size tiled left to right (up to three), or on two rows
/// (more than three; an empty cell stays black).
Image tile(const std::vector<const Image*>& images);
/// The grid tile() uses for `n` images: columns and rows.
void tile_layout(int n, int& cols, int& rows);

/// One line for stderr about a finished video: path, frames, size, rate, encoder.
std::string video_summary(const VideoWriter& video, double fps);

}  // namespace foveate::bench
