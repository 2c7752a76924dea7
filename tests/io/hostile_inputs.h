// Hostile inputs of issue 47, made in the test from the shared clips (kData): FBX
// files with a zlib bomb or a lying array count spliced in, glTF files written by
// rotinterp from a shared BVH and then mutated (times, values, offsets, names, buffer
// uris), a GLB whose chunk lengths lie, and a sparse BVH. Nothing is copied into the
// project; every file goes to the caller's temporary folder.
#pragma once

#include "io_test_util.h"
#include "support/run_cli.h"

#include <nlohmann/json.hpp>
#include <zlib.h>

#include <sys/stat.h>

#include <cstdint>
#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace rotinterp::test {

namespace fs = std::filesystem;

inline std::string bytes_of(const fs::path& p) { return read_text(p); }

inline void put_u32(std::string& b, std::size_t at, std::uint32_t v) { std::memcpy(&b[at], &v, 4); }
inline void put_f32(std::string& b, std::size_t at, float v) { std::memcpy(&b[at], &v, 4); }
inline std::uint64_t get_uint(const std::string& b, std::size_t at, bool wide) {
  std::uint64_t v = 0;
  std::memcpy(&v, &b[at], wide ? 8 : 4);
  return v;
}

// `n` zero bytes as one zlib stream (what a bomb holds: ~1 KB per MB), deflated a
// MiB at a time so that the test never holds the zeros.
inline std::string zlib_zeros(std::size_t n) {
  const std::string chunk(std::size_t{1} << 20, '\0');
  z_stream z{};
  deflateInit(&z, 9);
  std::string out;
  char buf[1 << 16];
  for (std::size_t left = n;;) {
    const std::size_t take = std::min(left, chunk.size());
    z.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(chunk.data()));
    z.avail_in = static_cast<uInt>(take);
    left -= take;
    const int flush = left == 0 ? Z_FINISH : Z_NO_FLUSH;
    int rc = Z_OK;
    do {
      z.next_out = reinterpret_cast<Bytef*>(buf);
      z.avail_out = sizeof buf;
      rc = deflate(&z, flush);
      out.append(buf, sizeof buf - z.avail_out);
    } while (z.avail_out == 0);
    if (rc == Z_STREAM_END || left == 0) break;
  }
  deflateEnd(&z);
  return out;
}

// A binary FBX (6.1 or 7.x) with one more top-level node, "Bomb", holding one double
// array of `count` elements stored as `stored` (zlib): inserted where the top-level
// list's null record was, so that every offset before it stays right.
inline std::string fbx_with_zlib_array(const fs::path& source, std::uint32_t count, const std::string& stored) {
  std::string b = bytes_of(source);
  std::uint32_t version = 0;
  std::memcpy(&version, &b[23], 4);
  const bool wide = version >= 7500;
  const std::size_t field = wide ? 8 : 4;
  std::size_t pos = 27;
  while (get_uint(b, pos, wide) != 0) pos = static_cast<std::size_t>(get_uint(b, pos, wide));
  std::string prop(13, '\0');
  prop[0] = 'd';
  put_u32(prop, 1, count);
  put_u32(prop, 5, 1);  // zlib
  put_u32(prop, 9, static_cast<std::uint32_t>(stored.size()));
  prop += stored;
  const std::string name = "Bomb";
  const std::uint64_t end = pos + 3 * field + 1 + name.size() + prop.size();
  std::string record(3 * field, '\0');
  const std::uint64_t fields[3] = {end, 1, prop.size()};
  for (int i = 0; i < 3; ++i) std::memcpy(&record[static_cast<std::size_t>(i) * field], &fields[i], field);
  record += static_cast<char>(name.size()) + name + prop;
  return b.insert(pos, record);
}

// The shared 7.5 sausage with its first KeyTime array declaring `count` elements.
inline std::string fbx_with_key_count(std::uint32_t count) {
  std::string b = bytes_of(kData / "fbx/ufbx_maya_game_sausage_7500_binary_wiggle.fbx");
  const std::size_t at = b.find("KeyTime") + 7;  // then 'l', count, encoding, stored
  put_u32(b, at + 1, count);
  return b;
}

// `text` (an ASCII FBX) with the first `array` list (KeyTime, KeyValueFloat) `a: …`
// changed by `edit` (its comma-separated items).
template <class Edit>
std::string edit_ascii_array(std::string text, const std::string& array, Edit edit) {
  const std::size_t from = text.find("a: ", text.find(array + ": *")) + 3, to = text.find('\n', from);
  std::vector<std::string> items;
  for (std::size_t p = from; p <= to;) {
    const std::size_t q = std::min(text.find(',', p), to);
    items.push_back(text.substr(p, q - p));
    p = q + 1;
  }
  edit(items);
  std::string joined;
  for (const std::string& s : items) joined += (joined.empty() ? "" : ",") + s;
  return text.replace(from, to - from, joined);
}

// The same on the shared ASCII interpolation-modes clip (first curve: pCube1's X
// translation).
template <class Edit>
std::string fbx_ascii_with(const std::string& array, Edit edit) {
  return edit_ascii_array(bytes_of(kData / "fbx/ufbx_maya_interpolation_modes_7500_ascii.fbx"), array, edit);
}

// A glTF file (JSON with a .bin beside it) that rotinterp writes from a shared BVH.
struct GltfFile {
  nlohmann::json doc;
  std::string bin;

  // Byte offset in `bin` of accessor `a`'s first element.
  std::size_t offset_of(std::size_t a) const {
    const auto& acc = doc["accessors"][a];
    const auto& view = doc["bufferViews"][acc["bufferView"].get<std::size_t>()];
    return view.value("byteOffset", std::size_t{0}) + acc.value("byteOffset", std::size_t{0});
  }
  // The first rotation sampler of the first animation: its input and output accessors.
  std::pair<std::size_t, std::size_t> rotation_sampler() const {
    const auto& anim = doc["animations"][0];
    for (const auto& ch : anim["channels"])
      if (ch["target"]["path"] == "rotation") {
        const auto& s = anim["samplers"][ch["sampler"].get<std::size_t>()];
        return {s["input"].get<std::size_t>(), s["output"].get<std::size_t>()};
      }
    return {0, 0};
  }
  // Writes NAME (its buffer uri `uri`, NAME.bin when empty) and that .bin into `dir`.
  fs::path write(const fs::path& dir, const std::string& name, const std::string& uri = "") const {
    nlohmann::json d = doc;
    d["buffers"][0]["uri"] = uri.empty() ? name + ".bin" : uri;
    write_text(dir / name, d.dump());
    if (uri.empty()) write_text(dir / (name + ".bin"), bin);
    return dir / name;
  }
};

// The shared Bandai clip (22 joints, 51 frames) as rotinterp writes it to glTF.
inline GltfFile shared_gltf(const fs::path& dir) {
  const fs::path out = dir / "base" / "clip.gltf";
  fs::create_directories(out.parent_path());
  run_cli("resample " + (kData / "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh").string() + " -o " + out.string() +
          " -q");
  GltfFile g;
  g.doc = nlohmann::json::parse(read_text(out));
  g.bin = read_text(out.parent_path() / g.doc["buffers"][0]["uri"].get<std::string>());
  return g;
}

// The same clip as a GLB whose JSON chunk declares `json_length` bytes.
inline fs::path glb_with_json_length(const fs::path& dir, std::uint32_t json_length) {
  const fs::path glb = dir / "base" / "clip.glb";
  fs::create_directories(glb.parent_path());
  run_cli("resample " + (kData / "bvh/NC_bandai2_raise-up-both-hands_active_031.bvh").string() + " -o " + glb.string() +
          " -q");
  std::string b = bytes_of(glb);
  put_u32(b, 12, json_length);
  const fs::path out = dir / ("lying_json_" + std::to_string(json_length) + ".glb");
  write_text(out, b);
  return out;
}

// A sparse file of `size` bytes starting with `head` (no disk used past the head).
inline fs::path sparse_file(const fs::path& path, const std::string& head, std::uintmax_t size) {
  write_text(path, head);
  fs::resize_file(path, size);
  return path;
}

}  // namespace rotinterp::test
