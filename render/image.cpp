// image: the RGB image and its atomic PNG write.
#include "rotinterp/render/image.h"

#include "rotinterp/io/files/atomic_file.h"

#include <zlib.h>

#include <cstdlib>
#include <ostream>
#include <string>

namespace {

// stb_image_write's own deflate is slow and loose (≈ 50 ms and 70 kB for a
// 960×540 frame here); zlib behind its documented STBIW_ZLIB_COMPRESS hook is not.
// Level 2 (zlib's fast matcher) deflates a CMU frame in 3.2 ms to 79 kB, level 6 in
// 7.0 ms to 69 kB: deflate was a fifth of render's CPU, 14 % more bytes buy back half
// of it. Same pixels either way; the same pixels give the same bytes.
constexpr int kZlibLevel = 2;

unsigned char* zlib_compress(unsigned char* data, int length, int* out_length, int /*stb's quality*/) {
  uLongf size = compressBound(static_cast<uLong>(length));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (!out) return nullptr;
  if (compress2(out, &size, data, static_cast<uLong>(length), kZlibLevel) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_length = static_cast<int>(size);
  return out;
}

}  // namespace

// A private (static) copy of stb_image_write's PNG writer using zlib; the shared
// libstb keeps its own symbols.
#define STBIW_ZLIB_COMPRESS zlib_compress
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBI_WRITE_NO_STDIO
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#pragma GCC diagnostic ignored "-Wsign-compare"
#include <stb_image_write.h>
#pragma GCC diagnostic pop

namespace {
// The "up" filter on every row: as small as stb's per-row choice on these images
// (flat backgrounds, antialiased edges) at half the time. Set once, before any
// writer thread exists.
const bool kFilterChosen = (stbi_write_force_png_filter = 2, true);
}  // namespace

namespace rotinterp::render {

Status write_png(const Image& image, const std::filesystem::path& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
    return make_error(path.string() + ": cannot write an empty or malformed image");
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    (void)kFilterChosen;
    auto sink = [](void* context, void* data, int size) {
      static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
    };
    // stb fails only when an allocation does (its row filters, zlib's buffers).
    if (!stbi_write_png_to_func(sink, &out, image.width, image.height, 3, image.rgb.data(), image.width * 3))
      return make_error(path.string() + ": out of memory encoding the " + std::to_string(image.width) + "x" +
                        std::to_string(image.height) + " PNG");
    return Ok{};
  });
}

}  // namespace rotinterp::render
