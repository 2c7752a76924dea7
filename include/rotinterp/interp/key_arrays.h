// Keys held as flat numeric arrays, as numpy holds them: K times and, at each time,
// the quaternions of J joints, row-major (K, J, 4), float64 or float32, scalar-last
// (x, y, z, w) or scalar-first (w, x, y, z). The boundary where rounded data becomes
// the unit keys RotationTrack rule 3 asks for (unit_quat), and where every joint of
// such an array is interpolated at once (interpolate_key_arrays).
//
// The joint count is explicit: one track is J = 1, and J = 0 (an array of shape
// (K, 0, 4)) has no quaternion to read and gives an empty output.
#pragma once

#include "rotinterp/core/result.h"
#include "rotinterp/core/rotation.h"
#include "rotinterp/track/track.h"

#include <cstddef>
#include <string>

namespace rotinterp {

// The 4 components at p made unit into `unit`, in the same layout; false for a zero,
// NaN or infinite quaternion. Scaled by the largest component first: no overflow or
// underflow in the norm for finite components of any size (1e300 or 1e-320). Inline:
// called once per key, it is most of the cost of gathering them (unit_tracks).
inline bool unit_quat(const double* p, Eigen::Vector4d& unit) {
  const Eigen::Map<const Eigen::Vector4d> q(p);
  if (!q.allFinite()) return false;
  const double largest = q.cwiseAbs().maxCoeff();
  if (largest == 0.0) return false;
  const Eigen::Vector4d scaled = q / largest;
  unit = scaled / scaled.norm();
  return true;
}

// The quaternion whose 4 components are at p, in either layout, and back.
inline Quat quat_at(const double* p, bool scalar_first) {
  return scalar_first ? Quat(p[0], p[1], p[2], p[3]) : Quat(p[3], p[0], p[1], p[2]);
}
inline void put_quat(const Quat& q, double* p, bool scalar_first) {
  if (scalar_first) {
    p[0] = q.w(), p[1] = q.x(), p[2] = q.y(), p[3] = q.z();
  } else {
    p[0] = q.x(), p[1] = q.y(), p[2] = q.z(), p[3] = q.w();
  }
}

// Components are float64 or float32 (read as they are: each is exactly a double).
template <class Component>
struct KeyArrays {
  const double* times = nullptr;     // (keys,) seconds, strictly increasing
  const Component* quats = nullptr;  // (keys, joints, 4)
  std::size_t keys = 0;
  std::size_t joints = 0;
  bool scalar_first = false;
};

// The tracks of joints [first, first + count) into tracks[0 .. count), each key made
// unit on the way, read in one pass over the rows (the array is row-major). Returns the
// offset of the first of those joints with a key unit_quat refuses (its track is not
// whole), or count. first + count <= keys.joints.
template <class Component>
std::size_t unit_tracks(const KeyArrays<Component>& keys, std::size_t first, std::size_t count,
                        RotationTrack* tracks);

// What interpolate_key_arrays builds and writes.
struct KeyArraysCurve {
  std::string method;             // a registry name (interpolator.h)
  bool continued = false;         // continued at the end velocities (interp/continued.h)
  bool out_scalar_first = false;  // the output's layout
};

// The (n, keys.joints, 4) output `out` of every joint's curve at the n times `at`.
// Errors: a key unit_quat refuses ("joint 2, key 5 is not a finite non-zero
// quaternion"), or a track refused by the method (its message, after "joint 2: "
// where there are several joints). Joints
// whose curve is nothing but their keys (slerp, nlerp) are built together and
// written a block of times at a time, a row at once; the others one at a time, each
// curve freed before the next is built (31 c2 curves alive at once cost 11 000 page
// faults a call, more than the evaluation itself), their keys gathered 8 joints a pass.
template <class Component>
Status interpolate_key_arrays(const KeyArrays<Component>& keys, const double* at, std::size_t n,
                              const KeyArraysCurve& curve, double* out);

}  // namespace rotinterp
