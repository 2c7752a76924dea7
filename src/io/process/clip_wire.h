// The reader's private wire format: what one read of a file gave (a ClipFileInfo,
// or an error, its kind and the warnings before it) as bytes, so that the importer
// process can hand its reading to the parent (import.h). Both ends are the same
// build on the same machine: integers and doubles travel in native byte order,
// doubles bit for bit.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/record/clip_file.h"

#include <optional>
#include <string>
#include <string_view>

namespace rotinterp::wire {

// On failure `error` holds the read's one-line message and `info` only the
// warnings given before it.

std::string encode(const ReadOutcome& outcome);

// Rejects, with an error and without reading past the end, bytes that are not one
// whole encode() result: truncated, trailing bytes, impossible counts or values.
Result<ReadOutcome> decode(std::string_view bytes);

}  // namespace rotinterp::wire
