// BVH text straight into a clip (what read_clip runs), and what it shares with
// bvh_to_clip (bvh_to_clip.cpp, from a parsed table of values): the clip's frame,
// one row's keys and the split over two threads, so that both give the same keys
// bit for bit. Private to src/io.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/io/bvh.h"

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

struct StreamedBvh {
  Clip clip;
  std::size_t extra_rows = 0;  // data rows after the declared frames (ignored)
};

// bvh_to_clip(parse_bvh(text, label), name, threads), bit for bit and with the same
// errors (the first in file order), without the table of values: each data row is
// parsed into a row of doubles and turned into its frame's keys. Long files run on
// two threads, each parsing and converting its half of the rows.
Result<StreamedBvh> read_bvh_text(std::string_view text, const std::string& label, const std::string& name,
                                  unsigned threads = 0);

namespace bvh_clip {

// The clip of a parsed header (`file.values` unused): skeleton, layout, frame time and
// `frames` keys on every track (translation tracks where a joint has position
// channels) at k·frame_time, allocated but not set.
Clip empty_clip(const BvhFile& file, const std::string& name, std::size_t frames);

// One data row (`file.columns` values) into the keys of frame `f` of every joint:
// the rotation the product of the joint's rotation channels (as BvhFile::rotation),
// normalized and on the side of frame f − 1's key unless f is the first of its
// range; the translation as BvhFile::translation.
class RowToKeys {
 public:
  explicit RowToKeys(const BvhFile& file);
  void operator()(const double* row, std::size_t f, bool first_of_range, Clip& clip) const;

 private:
  struct JointColumns {
    std::vector<std::size_t> rotation_column;  // value column of each rotation channel, in order
    std::vector<int> rotation_axis;
    std::vector<std::size_t> position_column;
    std::vector<int> position_axis;
    Vec3 offset = Vec3::Zero();
  };
  std::vector<JointColumns> joints_;
};

// Whether frames × columns values are worth converting on two threads (then each
// thread has at least one frame).
bool worth_two_threads(std::size_t frames, std::size_t columns, unsigned threads);

// work(f0, f1) over the frames [0, frames): with `two_threads`, as [0, split) here and
// [split, frames) on a helper thread (its exception rethrown here); else, or when no
// thread can be started, all here. Returns the split (`frames` when one thread did
// all).
std::size_t run_in_halves(std::size_t frames, bool two_threads, const std::function<void(std::size_t, std::size_t)>& work);

// After run_in_halves: the keys from `split` on, each half sign-aligned on its own,
// turned to the side of the first half's last key.
void join_halves(Clip& clip, std::size_t split);

}  // namespace bvh_clip

}  // namespace rotinterp
