// BVH (Biovision Hierarchy) text: our own pass over a file's HIERARCHY and MOTION
// sections, and the BVH writer.
//
// assimp's BVH importer drops each joint's channel order, parses values as 32-bit
// floats, loses position channels unless a joint has exactly 6 channels, and
// accepts NaN, inf, a zero or negative Frame Time and a `Frames:` count beyond the
// data. read_clip() therefore runs this pass first: it validates the whole file
// and gives the layout, the exact Frame Time and (in double) every channel value.
//
// Semantics used throughout rotinterp:
//  * a joint's local rotation is R(c₁)·R(c₂)·… over its rotation channels in the
//    listed order (the first listed is outermost), angles in degrees;
//  * position channels REPLACE the matching component of the OFFSET (as assimp and
//    most tools do; files that carry position channels on every joint store the
//    offset itself in them); components without a channel keep the OFFSET.
#pragma once

#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/clip.h"
#include "rotinterp/core/result.h"
#include "rotinterp/io/files/limits.h"
#include "rotinterp/io/files/write_options.h"

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

struct BvhJoint {
  std::string name;
  int parent = -1;                // index into BvhFile::joints, −1 for a ROOT
  Vec3 offset = Vec3::Zero();
  std::vector<Channel> channels;  // CHANNELS line, in file order
  std::size_t first_column = 0;   // column of channels[0] in a motion row
};

struct BvhEndSite {
  int parent = -1;  // joint index
  Vec3 offset = Vec3::Zero();
};

struct BvhFile {
  std::vector<BvhJoint> joints;  // depth-first, as in the file
  std::vector<BvhEndSite> end_sites;
  std::size_t frames = 0;        // `Frames:` (≥ 1)
  double frame_time = 0.0;       // `Frame Time:` in seconds (> 0, finite)
  std::string frame_time_text;   // exactly as written
  std::size_t columns = 0;       // values per frame = Σ channels
  std::vector<double> values;    // frames × columns, row-major, all finite
  std::size_t extra_rows = 0;    // data rows after the declared frames (ignored)

  double value(std::size_t frame, std::size_t joint, std::size_t channel) const {
    return values[frame * columns + joints[joint].first_column + channel];
  }
  // The joint's local rotation at `frame` (product of its rotation channels).
  Quat rotation(std::size_t frame, std::size_t joint) const;
  // The joint's local translation at `frame` (position channels over the OFFSET).
  Vec3 translation(std::size_t frame, std::size_t joint) const;
  bool has_position_channels(std::size_t joint) const;
};

// Limits of what parse_bvh() accepts, each far beyond real files (mocap runs at
// 24–1000 Hz; the depth and name limits, kMaxJointDepth and kMaxNameBytes, are
// every reader's: io/files/limits.h). Outside them a file is refused with one line.
constexpr double kMinBvhFrameTime = 1e-6;         // seconds: 1 MHz
constexpr double kMaxBvhFrameTime = 3600.0;       // seconds: one frame an hour

// Parses BVH text. `label` (the file name) starts every error message, which also
// names the line, frame, joint and channel where it can, quoting at most a short
// excerpt of the text. Fails fast, without allocating for the declared frame count,
// when the data rows run out. Joints are parsed without recursion, so depth costs
// no stack. A UTF-8 byte order mark is skipped; UTF-16 text is refused as such.
Result<BvhFile> parse_bvh(std::string_view text, const std::string& label);

// The first bytes of a file (`head`; all of it where `whole_file`) checked as BVH up
// to its data rows, before the file is read whole: Ok where the head parses or is cut
// inside the header, parse_bvh's own error where the header fails within the head
// (io/files/limits.h kBvhHeadBytes).
Status check_bvh_head(std::string_view head, bool whole_file, const std::string& label);

// The skeleton of a parsed file: joints (names, parents, OFFSETs, identity rest
// rotations) and End Sites named "EndSite_<joint>".
Skeleton bvh_skeleton(const BvhFile& file);
// Its layout: every joint's CHANNELS, the Frame Time text and the rotation numbers.
BvhLayout bvh_layout(const BvhFile& file);

// A clip read entirely from the parsed file (double precision, no assimp). Key k
// is at k·frame_time; joints with position channels get translation tracks. The
// clip carries the file's layout (Clip::bvh_layout).
Clip bvh_to_clip(const BvhFile& file, const std::string& name, unsigned threads = 0);

// Writes `clip` as BVH text. Joints keep the clip's order (parents must come
// first), OFFSETs, End Sites and channel layout (Clip::bvh_layout, and its Frame
// Time text while that still parses to frame_time); joints without channels get
// `options.bvh_order` rotation channels, plus position channels where they have a
// translation track. Rotation values are the source file's own numbers where the
// rotation is the file's at one of its frame times (BvhSourceAngles: a same-rate
// round trip or a cut keeps its numbers), elsewhere the Euler angles, in each joint's
// channel order, nearest to the previous frame's (no ±180° wraps); 6 decimals.
// Needs frame_time > 0 and every multi-key track on the grid start + k·frame_time.
Status write_bvh(const Clip& clip, std::ostream& out, const WriteOptions& options, const std::string& label);

}  // namespace rotinterp
