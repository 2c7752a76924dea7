// The clip model: a skeleton and per-joint key tracks. Plain data, no file
// format in it; readers fill it, interpolators and metrics consume it.
//
// A joint's local transform at time t is  T(translation(t)) · R(rotation(t)),
// where rotation(t) is the joint's FULL local rotation in its parent's frame (what
// a file splits into pre-/post-rotations, a rest orientation or Euler channels, the
// reader has already multiplied together). translation(t) is the joint's
// translation track where it has one, else its rest offset.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/clip/source_record.h"
#include "rotinterp/clip/units.h"
#include "rotinterp/track/track.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

struct Joint {
  std::string name;
  int parent = -1;                       // index into Skeleton::joints, −1 for a root
  Vec3 offset = Vec3::Zero();            // rest translation in the parent's frame
  Quat rest_rotation = Quat::Identity(); // rest local rotation (identity where the file has none)
};

// An End Site: a leaf point with an offset from its joint and no channels.
struct EndSite {
  int parent = -1;  // joint index
  Vec3 offset = Vec3::Zero();
  std::string name;  // e.g. "EndSite_LeftHand"; informational
};

// Invariants (checked by validate()):
//  1. at least one joint; names non-empty and unique;
//  2. parent < own index (parents come first; readers keep a file's depth-first order);
//  3. offsets finite, rest rotations finite unit quaternions;
//  4. End Site parents are valid joint indices.
struct Skeleton {
  std::vector<Joint> joints;
  std::vector<EndSite> end_sites;

  int find(std::string_view name) const;  // joint index or −1
  Status validate() const;
};

struct Clip {
  std::string name;           // animation name (or the file's stem)
  Skeleton skeleton;
  // One track per joint (same order as skeleton.joints). A joint without keys in
  // the source has a single key: its rest rotation.
  std::vector<RotationTrack> rotations;
  // One entry per joint; empty where the joint has no translation keys.
  std::vector<std::optional<TranslationTrack>> translations;
  double frame_time = 0.0;    // seconds per frame of the source (as the file states it), 0 if none
  ClipUnit unit;              // metres per clip unit and where that came from (clip/units.h)
  std::string source_format;  // the source's format by its registry name (informational)
  std::size_t source_meshes = 0;  // meshes (with their skins) in the source: no writer keeps them
  // What the reader kept of its file for that format's writers, and the frame rate
  // the file states apart from its keys (clip/source_record.h); null if nothing.
  SourceRecordPtr source_record;

  // Invariants: skeleton valid; one rotation and one translation entry per joint;
  // every track valid.
  // The clip's description without its tracks (name, skeleton, unit, source format,
  // meshes, the record's rebuilt() part): what a rebuilt clip starts from. Its frame
  // time and the rest of its record are the caller's to set, as they hold only at
  // the source's frames.
  Clip without_tracks() const;
  Status validate() const;
  // Earliest and latest key time over all tracks.
  double start_time() const;
  double end_time() const;
  // Frames of a uniformly sampled source: round((end − start)/frame_time) + 1, or
  // the largest key count if frame_time is 0.
  std::size_t frame_count() const;
};

// Forward kinematics: world rotation and position of every joint, given local
// rotations and translations (one per joint). Optionally End Site positions.
struct WorldPose {
  std::vector<Quat> rotation;
  std::vector<Vec3> position;
  std::vector<Vec3> end_site_position;
};
void forward_kinematics(const Skeleton& skeleton, const std::vector<Quat>& local_rotation,
                        const std::vector<Vec3>& local_translation, WorldPose& out);

// The rest pose: every joint at its rest rotation and offset.
WorldPose rest_pose(const Skeleton& skeleton);

// The height used to express position errors as a percentage: the largest side of
// the bounding box of all joint and End Site positions in `pose`. 0 for a skeleton
// of one point (the caller then reports percentages against 1 unit).
double skeleton_height(const WorldPose& pose);

// The clip's metres per unit (Clip::unit), read through this one guard: 1 where it is
// not a positive finite number.
double metres_per_unit(const Clip& clip);
// `metres` in the clip's units.
double in_clip_units(const Clip& clip, double metres);

}  // namespace rotinterp
