// video: drawn frames piped raw to ffmpeg, the output committed atomically.
#include "rotinterp/render/video.h"

#include "rotinterp/io/files/atomic_file.h"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

extern char** environ;

namespace rotinterp::render {

namespace fs = std::filesystem;

Result<VideoFormat> video_format(const fs::path& path) {
  std::string ext = path.extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (ext == ".mp4") return VideoFormat::mp4;
  if (ext == ".gif") return VideoFormat::gif;
  return make_error("--video '" + path.string() + "': unknown format (use .mp4 or .gif)");
}

Status check_video_size(VideoFormat format, int width, int height) {
  if (format == VideoFormat::mp4 && (width % 2 != 0 || height % 2 != 0))
    return make_error(fmt::format("--video: H.264 (.mp4) needs an even width and height, not {}x{}", width, height));
  return Ok{};
}

struct VideoWriter::Impl {
  fs::path target;
  int width = 0, height = 0;
  std::unique_ptr<AtomicOutput> out;
  pid_t pid = -1;
  int input = -1;            // our end of the socket that is ffmpeg's stdin
  std::FILE* log = nullptr;  // ffmpeg's stderr
  std::size_t frames = 0;
  bool finished = false;

  ~Impl() {
    if (input >= 0) ::close(input);
    if (pid > 0) {
      ::kill(pid, SIGKILL);
      int status = 0;
      while (::waitpid(pid, &status, 0) < 0 && errno == EINTR) {
      }
    }
    if (log) std::fclose(log);
  }

  // ffmpeg's last non-empty line of output, or `fallback`.
  std::string last_message(const std::string& fallback) const {
    if (!log) return fallback;
    std::fflush(log);
    std::rewind(log);
    std::string line, last;
    char buffer[512];
    while (std::fgets(buffer, sizeof buffer, log)) {
      line += buffer;
      if (!line.empty() && line.back() == '\n') {
        while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
        if (!line.empty()) last = line;
        line.clear();
      }
    }
    while (!line.empty() && std::isspace(static_cast<unsigned char>(line.back()))) line.pop_back();
    if (!line.empty()) last = line;
    return last.empty() ? fallback : last;
  }

  // Waits for ffmpeg; its failure as one line.
  Status wait() {
    int status = 0;
    pid_t r;
    while ((r = ::waitpid(pid, &status, 0)) < 0 && errno == EINTR) {
    }
    pid = -1;
    if (r < 0) return make_error(target.string() + ": ffmpeg: " + std::strerror(errno));
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return Ok{};
    const std::string how = WIFSIGNALED(status) ? fmt::format("killed by signal {}", WTERMSIG(status))
                                                : fmt::format("exit status {}", WEXITSTATUS(status));
    return make_error(target.string() + ": ffmpeg failed: " + last_message(how));
  }
};

VideoWriter::VideoWriter(std::unique_ptr<Impl> impl) : impl_(std::move(impl)) {}
VideoWriter::~VideoWriter() = default;
std::size_t VideoWriter::frames() const { return impl_->frames; }

Result<std::unique_ptr<VideoWriter>> VideoWriter::open(const fs::path& path, int width, int height, double fps) {
  auto format = video_format(path);
  if (!format) return format.failure();
  if (Status s = check_video_size(*format, width, height); !s) return s.failure();
  if (width < 1 || height < 1) return make_error(path.string() + ": cannot encode an empty image");
  if (!(fps > 0.0) || fps > 1000.0) return make_error(fmt::format("--video-fps {} is outside (0, 1000]", fps));
  auto impl = std::make_unique<Impl>();
  impl->target = path;
  impl->width = width;
  impl->height = height;
  impl->out = std::make_unique<AtomicOutput>(path, TempKind::named);  // ffmpeg opens a path
  if (Status s = impl->out->status(); !s) return s.failure();

  const std::string size = fmt::format("{}x{}", width, height);
  const std::string rate = fmt::format("{:.9g}", fps);
  std::vector<std::string> args = {"ffmpeg", "-hide_banner", "-nostats", "-loglevel", "error", "-y",
                                   "-f", "rawvideo", "-pix_fmt", "rgb24", "-s", size, "-framerate", rate,
                                   "-i", "pipe:0", "-an", "-map_metadata", "-1", "-fflags", "+bitexact"};
  if (*format == VideoFormat::mp4) {
    for (const char* a : {"-c:v", "libx264", "-preset", "veryfast", "-crf", "18", "-pix_fmt", "yuv420p",
                          "-flags:v", "+bitexact", "-movflags", "+faststart", "-f", "mp4"})
      args.emplace_back(a);
  } else {
    for (const char* a : {"-filter_complex", "split[a][b];[a]palettegen=stats_mode=full[p];[b][p]paletteuse=dither=sierra2_4a",
                          "-loop", "0", "-f", "gif"})
      args.emplace_back(a);
  }
  args.push_back(impl->out->temp_path().string());

  int sockets[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0)
    return make_error(path.string() + ": cannot start ffmpeg: " + std::strerror(errno));
  impl->input = sockets[0];
  impl->log = std::tmpfile();
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, sockets[1], 0);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  if (impl->log) posix_spawn_file_actions_adddup2(&actions, ::fileno(impl->log), 2);
  std::vector<char*> argv;
  for (std::string& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = -1;
  const int err = ::posix_spawnp(&pid, "ffmpeg", &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  ::close(sockets[1]);
  if (err != 0)
    return make_error(path.string() + ": cannot run ffmpeg (Debian package ffmpeg): " + std::strerror(err));
  impl->pid = pid;
  return std::unique_ptr<VideoWriter>(new VideoWriter(std::move(impl)));
}

Status VideoWriter::write(const Image& image) {
  Impl& m = *impl_;
  if (m.finished || m.input < 0) return make_error(m.target.string() + ": the video is already finished");
  if (image.width != m.width || image.height != m.height)
    return make_error(fmt::format("{}: a {}x{} frame in a {}x{} video", m.target.string(), image.width, image.height,
                                  m.width, m.height));
  const auto* data = reinterpret_cast<const char*>(image.rgb.data());
  std::size_t left = image.rgb.size();
  while (left > 0) {
    const ssize_t n = ::send(m.input, data, left, MSG_NOSIGNAL);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {  // ffmpeg has gone: say why
      ::close(m.input);
      m.input = -1;
      Status s = m.wait();
      return s ? make_error(m.target.string() + ": ffmpeg stopped reading frames") : s;
    }
    data += n;
    left -= static_cast<std::size_t>(n);
  }
  ++m.frames;
  return Ok{};
}

Status VideoWriter::finish() {
  Impl& m = *impl_;
  if (m.finished) return make_error(m.target.string() + ": the video is already finished");
  m.finished = true;
  if (m.input >= 0) {
    ::close(m.input);
    m.input = -1;
  }
  if (m.pid > 0)
    if (Status s = m.wait(); !s) return s;
  if (m.frames == 0) return make_error(m.target.string() + ": no frames to encode");
  return m.out->commit();
}

}  // namespace rotinterp::render
