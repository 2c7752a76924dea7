// What a reader keeps of its file beside the clip model (clip/source_record.h): the
// BVH layout (bvh_layout.h), which the BVH writer gives back and the FBX writer keeps
// each joint's rotation order from, and the frame rate the file states apart from its
// keys (FBX GlobalSettings TimeMode / CustomFrameRate). Readers set it, writers and
// `info` read it, through the functions below; the clip layer only passes it on.
#pragma once

#include "rotinterp/clip/clip.h"
#include "rotinterp/clip/source_record.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/files/bvh_layout.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace rotinterp {

struct SynthOptions;  // clip/synth.h

struct FileRecord final : SourceRecord {
  double rate_hz = 0.0;                 // the file's own frame rate, Hz; 0 if it states none
  std::optional<BvhLayout> bvh_layout;  // a BVH source's layout (or one kept through FBX)

  double stated_rate_hz() const override;
  SourceRecordPtr retimed() const override;              // the layout without its Frame Time text
  SourceRecordPtr cut(std::size_t frames) const override;  // the source's frames found that far on
  SourceRecordPtr rebuilt() const override;              // the file's rate alone
};

// The clip's file record, BVH layout and Frame Time text as written; null or empty
// where the clip has none.
const FileRecord* file_record(const Clip& clip);
const BvhLayout* bvh_layout(const Clip& clip);
const std::string& frame_time_text(const Clip& clip);
// Joint `joint`'s channels in the clip's layout; empty when it has none (a clip
// that is not from BVH, or a joint without CHANNELS).
const std::vector<Channel>& bvh_channels(const Clip& clip, std::size_t joint);

// The clip with a new record that has `layout` (none: no layout) / the file's rate,
// the rest of its record kept.
void set_bvh_layout(Clip& clip, std::optional<BvhLayout> layout);
void set_file_rate_hz(Clip& clip, double rate_hz);

// make_synth_clip(options) (clip/synth.h) with a layout that keys each joint's
// rotation in its motion's rotation order, roots' Xposition Yposition Zposition
// first: what `rotinterp synth` writes.
Result<Clip> make_synth_file_clip(const SynthOptions& options);

}  // namespace rotinterp
