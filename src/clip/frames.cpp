// A clip's frame grid, its tracks sampled at every frame, kept key frames and bone axes.
#include "rotinterp/clip/frames.h"

#include "rotinterp/track/sample.h"

#include <algorithm>
#include <cmath>

namespace rotinterp {

double FrameGrid::exact_time(std::size_t k) const {
  return rate ? start + rate->time_of(static_cast<std::int64_t>(k)) : times[k];
}

std::optional<std::size_t> FrameGrid::frame_at(double t) const {
  const auto it = std::lower_bound(times.begin(), times.end(), t - snap);
  if (it == times.end() || std::abs(*it - t) > snap) return std::nullopt;
  return static_cast<std::size_t>(it - times.begin());
}

std::optional<Rate> clip_rate(const Clip& clip) {
  if (!(clip.frame_time > 0.0)) return std::nullopt;
  auto r = rate_from_frame_time(clip.frame_time);
  if (!r) return std::nullopt;
  return r.value();
}

FrameGrid frame_grid(const Clip& clip) {
  FrameGrid g;
  g.start = clip.start_time();
  if (clip.frame_time > 0.0) {
    g.frame_time = clip.frame_time;
    g.rate = clip_rate(clip);
    const std::size_t n = clip.frame_count();
    const double end = clip.end_time();
    g.times.resize(n);
    for (std::size_t k = 0; k < n; ++k) g.times[k] = std::min(g.start + static_cast<double>(k) * clip.frame_time, end);
    if (n > 1) g.times[n - 1] = end;
    g.snap = kFrameSnap * clip.frame_time;
    return g;
  }
  const RotationTrack* longest = &clip.rotations.front();
  for (const RotationTrack& r : clip.rotations)
    if (r.times.size() > longest->times.size()) longest = &r;
  g.times = longest->times;
  if (g.times.size() > 1)
    g.snap = kFrameSnap * (g.times.back() - g.times.front()) / static_cast<double>(g.times.size() - 1);
  return g;
}

DenseClip dense_clip(const Clip& clip) {
  DenseClip d;
  d.grid = frame_grid(clip);
  const std::size_t nj = clip.skeleton.joints.size(), nf = d.grid.size();
  d.rotation.assign(nj, std::vector<Quat>(nf));
  d.translation.assign(nj, std::vector<Vec3>(nf));
  for (std::size_t j = 0; j < nj; ++j) {
    sample_rotations(clip.rotations[j], d.grid.times, d.grid.snap, d.rotation[j].data());
    if (clip.translations[j])
      sample_translations(*clip.translations[j], d.grid.times, d.grid.snap, d.translation[j].data());
    else
      std::fill(d.translation[j].begin(), d.translation[j].end(), clip.skeleton.joints[j].offset);
  }
  return d;
}

DenseClip exact_dense_clip(const Clip& clip) {
  DenseClip d = dense_clip(clip);
  if (d.grid.rate) {
    for (std::size_t k = 0; k < d.grid.size(); ++k) d.grid.times[k] = d.grid.exact_time(k);
    d.grid.frame_time = d.grid.rate->period();
  }
  return d;
}

std::vector<std::size_t> keep_every_indices(std::size_t frames, std::size_t n) {
  std::vector<std::size_t> out;
  if (frames == 0) return out;
  if (n == 0) n = 1;
  for (std::size_t i = 0; i < frames; i += n) out.push_back(i);
  if (out.back() != frames - 1) out.push_back(frames - 1);
  return out;
}

RotationTrack decimated_track(const std::vector<double>& times, const std::vector<Quat>& rotations,
                              const std::vector<std::size_t>& key_frames) {
  RotationTrack track;
  track.times.reserve(key_frames.size());
  track.keys.reserve(key_frames.size());
  for (std::size_t k : key_frames) {
    track.times.push_back(times[k]);
    track.keys.push_back(rotations[k]);
  }
  track.make_sign_continuous();
  return track;
}

std::vector<Vec3> bone_axes(const Skeleton& skeleton) {
  const std::size_t n = skeleton.joints.size();
  std::vector<Vec3> axis(n, Vec3::Zero());
  std::vector<double> longest(n, 0.0);
  auto consider = [&](int parent, const Vec3& offset) {
    if (parent < 0 || static_cast<std::size_t>(parent) >= n || !offset.allFinite()) return;
    const double len = offset.norm();
    if (len > longest[parent]) {
      longest[parent] = len;
      axis[parent] = offset / len;
    }
  };
  for (const Joint& j : skeleton.joints) consider(j.parent, j.offset);
  for (const EndSite& e : skeleton.end_sites) consider(e.parent, e.offset);
  for (std::size_t i = 0; i < n; ++i) {
    if (longest[i] > 0.0) continue;
    const Joint& j = skeleton.joints[i];
    const Vec3 own = normalized_or_identity(j.rest_rotation).conjugate() * j.offset;
    const double len = own.norm();
    axis[i] = (len > 0.0 && std::isfinite(len)) ? Vec3(own / len) : Vec3::UnitX();
  }
  return axis;
}

}  // namespace rotinterp
