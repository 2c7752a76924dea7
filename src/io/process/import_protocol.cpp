// The importer's request and reply framing (import_protocol.h).
#include "import_protocol.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

namespace rotinterp::detail::import_protocol {

namespace {

void put_u32(std::string& out, std::uint32_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }

void put_field(std::string& out, std::string_view field) {
  put_u32(out, static_cast<std::uint32_t>(field.size()));
  out.append(field);
}

// A double as text that reads back as the same double.
std::string exact_text(double v) {
  char buf[40];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace

std::string encode_request(const std::filesystem::path& path, const ReadOptions& options) {
  std::string body;
  put_field(body, path.native());
  put_field(body, options.animation);
  put_field(body, options.fold_fbx_helpers ? "1" : "0");
  put_field(body, options.cross_check_with_assimp ? "1" : "0");
  put_field(body, options.read_curves ? "1" : "0");
  put_field(body, options.unit ? exact_text(*options.unit) : std::string());
  put_field(body, options.allow_external_files ? "1" : "0");
  put_field(body, options.read_body ? "1" : "0");
  std::string out;
  put_u32(out, static_cast<std::uint32_t>(body.size()));
  return out + body;
}

std::optional<Request> decode_request(std::string_view body) {
  std::vector<std::string> fields;
  while (!body.empty()) {
    std::uint32_t n = 0;
    if (body.size() < sizeof n) return std::nullopt;
    std::memcpy(&n, body.data(), sizeof n);
    body.remove_prefix(sizeof n);
    if (body.size() < n) return std::nullopt;
    fields.emplace_back(body.substr(0, n));
    body.remove_prefix(n);
  }
  if (fields.size() != 8) return std::nullopt;
  Request r;
  r.path = fields[0];
  r.options.animation = fields[1];
  r.options.fold_fbx_helpers = fields[2] == "1";
  r.options.cross_check_with_assimp = fields[3] == "1";
  r.options.read_curves = fields[4] == "1";
  if (!fields[5].empty()) r.options.unit = std::strtod(fields[5].c_str(), nullptr);
  r.options.allow_external_files = fields[6] == "1";
  r.options.read_body = fields[7] == "1";
  return r;
}

std::string reply_header(std::size_t payload_size) {
  std::string out(kReplyMagic);
  const auto n = static_cast<std::uint64_t>(payload_size);
  out.append(reinterpret_cast<const char*>(&n), sizeof n);
  return out;
}

std::optional<std::uint64_t> payload_size(std::string_view header) {
  if (header.size() != kReplyHeader || header.substr(0, kReplyMagic.size()) != kReplyMagic) return std::nullopt;
  std::uint64_t n = 0;
  std::memcpy(&n, header.data() + kReplyMagic.size(), sizeof n);
  return n;
}

}  // namespace rotinterp::detail::import_protocol
