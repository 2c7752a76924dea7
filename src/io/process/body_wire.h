// A character's body (io/record/character_body.h) on the reader's wire (clip_wire.h):
// field by field, float arrays bit for bit. Private to src/io/process.
#pragma once

#include "rotinterp/io/record/character_body.h"
#include "wire_bytes.h"

namespace rotinterp::wire {

void put(Writer& w, const CharacterBody& body);
// Counts are checked against the bytes left; indices and values are the writer's
// to check (io/gltf: a body is validated before it is written).
void get(Reader& r, CharacterBody& body);

}  // namespace rotinterp::wire
