#include "rotinterp/render/image.h"

#include "rotinterp/io/atomic_file.h"

#include <stb_image_write.h>

#include <ostream>

namespace rotinterp::render {

Status write_png(const Image& image, const std::filesystem::path& path) {
  if (image.width <= 0 || image.height <= 0 ||
      image.rgb.size() != static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 3)
    return make_error(path.string() + ": cannot write an empty or malformed image");
  return write_file_atomically(path, [&](std::ostream& out) -> Status {
    auto sink = [](void* context, void* data, int size) {
      static_cast<std::ostream*>(context)->write(static_cast<const char*>(data), size);
    };
    if (!stbi_write_png_to_func(sink, &out, image.width, image.height, 3, image.rgb.data(), image.width * 3))
      return make_error(path.string() + ": PNG encoding failed");
    return Ok{};
  });
}

}  // namespace rotinterp::render
