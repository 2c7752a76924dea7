// The importer's conversation with the reader (import.h): one request (a path and
// the read's options) in on its standard input, one framed reply (the outcome in
// clip_wire.h's format) out on its standard output, for as many files as it is
// sent. Both ends come from the same build: integers travel in native byte order.
#pragma once

#include "rotinterp/io/record/read_options.h"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace rotinterp::detail::import_protocol {

// The importer's first argument: a mismatch means the two come from different builds.
constexpr std::string_view kVersion = "rotinterp-import-5";

// A request: its body's length (uint32), then the body.
constexpr std::size_t kRequestHeader = sizeof(std::uint32_t);
constexpr std::uint32_t kMaxRequestBody = 1u << 24;  // paths and take names are far shorter

// What the importer needs of a read: the path and the options that change the reading.
struct Request {
  std::filesystem::path path;
  ReadOptions options;
};

std::string encode_request(const std::filesystem::path& path, const ReadOptions& options);
// The body after its length; nothing when it is not one whole request.
std::optional<Request> decode_request(std::string_view body);

// A reply: these 8 bytes, the payload's length (uint64), the payload
// (wire::encode's bytes). Anything else on the socket is not a reply.
constexpr std::string_view kReplyMagic = "rimpREPL";
constexpr std::size_t kReplyHeader = 16;

std::string reply_header(std::size_t payload_size);
// The payload's length, or nothing when `header` (kReplyHeader bytes) is not a reply's.
std::optional<std::uint64_t> payload_size(std::string_view header);

}  // namespace rotinterp::detail::import_protocol
