// Encoding drawn frames into a video through Debian's ffmpeg (a separate process:
// the frames are piped to it raw as they are drawn; nothing else touches disk).
//
//  * .mp4 — H.264 (libx264, CRF 18, yuv420p, +faststart), so width and height must
//    be even (4:2:0 chroma);
//  * .gif — one 256-colour palette for the whole clip (palettegen over every
//    frame, then paletteuse with Sierra-2-4A dithering), looping; ffmpeg keeps
//    the frames in memory until the palette is made.
//
// Atomic like every output (io/files/atomic_file.h): ffmpeg writes a named temporary
// next to the target, renamed onto it by finish() once ffmpeg has exited
// cleanly. On any failure — ffmpeg missing or failing, a write refused — the
// target keeps its previous content and the temporary is removed.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/render/image.h"

#include <filesystem>
#include <memory>
#include <string>

namespace rotinterp::render {

enum class VideoFormat { mp4, gif };

// The format of `path` from its extension (.mp4 or .gif, any case); an error
// naming both otherwise.
Result<VideoFormat> video_format(const std::filesystem::path& path);

// A width × height size the format can take (mp4: both even); the error is one line.
Status check_video_size(VideoFormat format, int width, int height);

class VideoWriter {
 public:
  // Starts ffmpeg writing `path` at `fps` frames per second (> 0, at most 1000).
  // Errors: an unknown extension, an odd size for mp4, ffmpeg not found, the
  // directory not writable.
  static Result<std::unique_ptr<VideoWriter>> open(const std::filesystem::path& path, int width, int height,
                                                   double fps);
  ~VideoWriter();  // unfinished: ffmpeg is stopped, the temporary removed
  VideoWriter(const VideoWriter&) = delete;
  VideoWriter& operator=(const VideoWriter&) = delete;

  // Sends one frame (exactly width × height). Blocks while ffmpeg is behind.
  Status write(const Image& image);
  // Ends the stream, waits for ffmpeg and renames the file onto its target. The
  // error is one line: ffmpeg's last message when it failed.
  Status finish();

  std::size_t frames() const;

 private:
  struct Impl;
  explicit VideoWriter(std::unique_ptr<Impl> impl);
  std::unique_ptr<Impl> impl_;
};

}  // namespace rotinterp::render
