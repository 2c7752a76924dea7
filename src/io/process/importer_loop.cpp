// The importer's side of import.h: importer_main() answers the reader's requests,
// one file after another, until its standard input ends.
#include "rotinterp/io/process/importer.h"
#include "clip_wire.h"
#include "import_protocol.h"
#include "rotinterp/io/import/import.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>

namespace rotinterp::detail {

namespace {

namespace protocol = import_protocol;

bool write_all(int fd, std::string_view bytes) {
  while (!bytes.empty()) {
    const ssize_t put = ::write(fd, bytes.data(), bytes.size());
    if (put < 0 && errno == EINTR) continue;
    if (put <= 0) return false;
    bytes.remove_prefix(static_cast<std::size_t>(put));
  }
  return true;
}

enum class Got { whole, end, cut };

// `size` bytes from fd into `out`: end when the input ended before the first byte.
Got read_exact(int fd, std::string& out, std::size_t size) {
  out.resize(size);
  std::size_t have = 0;
  while (have < size) {
    const ssize_t n = ::read(fd, out.data() + have, size - have);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return have == 0 ? Got::end : Got::cut;
    have += static_cast<std::size_t>(n);
  }
  return Got::whole;
}

}  // namespace

int importer_main(int argc, char** argv) {
  if (argc != 3 || argv[1] != protocol::kVersion) {
    std::fprintf(stderr, "rotinterp-import: the importer of rotinterp's reader, started by it; not a command\n");
    return 2;
  }
  // Dies with the thread that started it, even in a process killed by SIGKILL;
  // does nothing if that one is gone already.
  ::prctl(PR_SET_PDEATHSIG, SIGKILL);
  if (std::to_string(::getppid()) != argv[2]) return 3;
  // The replies get a descriptor of their own; anything a library prints to
  // stdout goes nowhere instead of into a reply.
  const int reply = ::fcntl(STDOUT_FILENO, F_DUPFD_CLOEXEC, 3);
  if (const int null = ::open("/dev/null", O_WRONLY); null >= 0) ::dup2(null, STDOUT_FILENO);
  if (reply < 0) return 4;
  // _exit everywhere: no exit handlers, so LeakSanitizer does not turn assimp's
  // leaks on a bad file into a failed import.
  std::string header, body;
  for (;;) {
    const Got got = read_exact(STDIN_FILENO, header, protocol::kRequestHeader);
    if (got == Got::end) ::_exit(0);  // the reader is done with this importer
    std::uint32_t size = 0;
    if (got == Got::whole) std::memcpy(&size, header.data(), sizeof size);
    if (got != Got::whole || size > protocol::kMaxRequestBody || read_exact(STDIN_FILENO, body, size) != Got::whole)
      ::_exit(5);
    const std::optional<protocol::Request> request = protocol::decode_request(body);
    if (!request) ::_exit(5);
    const std::string payload = wire::encode(read_in_this_process(request->path, request->options));
    if (!write_all(reply, protocol::reply_header(payload.size())) || !write_all(reply, payload)) ::_exit(1);
  }
}

}  // namespace rotinterp::detail
