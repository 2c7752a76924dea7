// The reader's private wire format (clip_wire.h): a read's outcome, clip and FBX
// curves field by field; arrays as a count followed by their items (wire_bytes.h).
#include "clip_wire.h"
#include "body_wire.h"
#include "wire_bytes.h"

#include "rotinterp/io/files/file_errors.h"
#include "rotinterp/io/files/file_record.h"

#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>

namespace rotinterp::wire {

namespace {

// Also the format's version: bytes from another build fail here, not in a field.
constexpr std::string_view kMagic = "rotinterp-clip-wire-7";

// Smallest encoded sizes, for Reader::count.
constexpr std::size_t kCount = 8, kDouble = 8, kVec3 = 3 * kDouble, kQuat = 4 * kDouble;
constexpr std::size_t kString = kCount;

// What a reading in the importer can fail with: `other` or a file kind (the process
// kinds are given by the parent, never sent).
bool sendable_kind(std::uint8_t code) {
  if (code == static_cast<std::uint8_t>(ErrorKind::other)) return true;
  for (ErrorKind k : file_error::all)
    if (code == static_cast<std::uint8_t>(k)) return true;
  return false;
}

void put(Writer& w, const std::vector<double>& v) {
  w.u64(v.size());
  for (double x : v) w.f64(x);
}
void get(Reader& r, std::vector<double>& v) {
  v.resize(r.count(kDouble));
  for (double& x : v) x = r.f64();
}

void put(Writer& w, const Clip& clip) {
  w.str(clip.name);
  w.u64(clip.skeleton.joints.size());
  for (std::size_t i = 0; i < clip.skeleton.joints.size(); ++i) {
    const Joint& j = clip.skeleton.joints[i];
    w.str(j.name);
    w.i64(j.parent);
    w.vec3(j.offset);
    w.quat(j.rest_rotation);
    const std::vector<Channel>& channels = bvh_channels(clip, i);
    w.u64(channels.size());
    for (Channel c : channels) w.u8(static_cast<std::uint8_t>(c));
  }
  w.u64(clip.skeleton.end_sites.size());
  for (const EndSite& e : clip.skeleton.end_sites) {
    w.i64(e.parent);
    w.vec3(e.offset);
    w.str(e.name);
  }
  w.u64(clip.rotations.size());
  for (const RotationTrack& t : clip.rotations) {
    put(w, t.times);
    w.u64(t.keys.size());
    for (const Quat& q : t.keys) w.quat(q);
  }
  w.u64(clip.translations.size());
  for (const std::optional<TranslationTrack>& t : clip.translations) {
    w.u8(t.has_value());
    if (!t) continue;
    put(w, t->times);
    w.u64(t->keys.size());
    for (const Vec3& v : t->keys) w.vec3(v);
  }
  w.f64(clip.frame_time);
  w.str(frame_time_text(clip));
  w.f64(clip.unit.metres_per_unit);
  w.u8(static_cast<std::uint8_t>(clip.unit.origin));
  w.str(clip.unit.reason);
  w.str(clip.source_format);
  w.u64(clip.source_meshes);
  w.f64(stated_rate_hz(clip.source_record));
}

void get(Reader& r, Clip& clip) {
  clip.name = r.str();
  clip.skeleton.joints.resize(r.count(kString + 8 + kVec3 + kQuat + kCount));
  // The layout travels as each joint's channels and the Frame Time text: a clip
  // has one when any of them is there.
  BvhLayout layout;
  bool has_layout = false;
  for (Joint& j : clip.skeleton.joints) {
    j.name = r.str();
    j.parent = r.index();
    j.offset = r.vec3();
    j.rest_rotation = r.quat();
    std::vector<Channel>& channels = layout.channels.emplace_back(r.count(1));
    has_layout = has_layout || !channels.empty();
    for (Channel& c : channels) {
      const std::uint8_t v = r.u8();
      if (v > static_cast<std::uint8_t>(Channel::Zrotation)) r.fail();
      c = static_cast<Channel>(v);
    }
  }
  clip.skeleton.end_sites.resize(r.count(8 + kVec3 + kString));
  for (EndSite& e : clip.skeleton.end_sites) {
    e.parent = r.index();
    e.offset = r.vec3();
    e.name = r.str();
  }
  clip.rotations.resize(r.count(2 * kCount));
  for (RotationTrack& t : clip.rotations) {
    get(r, t.times);
    t.keys.resize(r.count(kQuat));
    for (Quat& q : t.keys) q = r.quat();
  }
  clip.translations.resize(r.count(1));
  for (std::optional<TranslationTrack>& t : clip.translations) {
    if (!r.flag()) continue;
    t.emplace();
    get(r, t->times);
    t->keys.resize(r.count(kVec3));
    for (Vec3& v : t->keys) v = r.vec3();
  }
  clip.frame_time = r.f64();
  layout.frame_time_text = r.str();
  clip.unit.metres_per_unit = r.f64();
  const std::uint8_t origin = r.u8();
  if (origin > static_cast<std::uint8_t>(UnitOrigin::assumed)) r.fail();
  clip.unit.origin = static_cast<UnitOrigin>(origin);
  clip.unit.reason = r.str();
  clip.source_format = r.str();
  clip.source_meshes = r.size();
  auto record = std::make_shared<FileRecord>();
  record->rate_hz = r.f64();
  if (has_layout || !layout.frame_time_text.empty()) record->bvh_layout = std::move(layout);
  if (record->rate_hz != 0.0 || record->bvh_layout) clip.source_record = std::move(record);
}

// The FBX curves as read (io/fbx/fbx_curves.h): takes, layers, curves, keys, models.
constexpr std::size_t kKey = 8 + 8 + 1 + 1 + 8 + 2 * kDouble + 2 + 2 * kDouble + 2 + 2 * kDouble + 3 * kDouble;
constexpr std::size_t kFbxVec3 = 3 * kDouble;

void put(Writer& w, const FbxVec3& v) {
  for (double x : v) w.f64(x);
}
void get(Reader& r, FbxVec3& v) {
  for (double& x : v) x = r.f64();
}

void put(Writer& w, const FbxCurve& c) {
  w.str(c.node);
  w.str(c.property);
  w.u8(static_cast<std::uint8_t>(c.channel));
  w.u64(c.layer);
  w.f64(c.default_value);
  for (const FbxExtrapolationRule* e : {&c.pre, &c.post}) {
    w.u8(static_cast<std::uint8_t>(e->mode));
    w.i64(e->repetitions);
  }
  w.u64(c.keys.size());
  for (const FbxKey& k : c.keys) {
    w.i64(k.ticks);
    w.f64(k.value);
    w.u8(static_cast<std::uint8_t>(k.interpolation));
    w.u8(static_cast<std::uint8_t>(k.tangent));
    w.u64(k.flags);
    w.f64(k.right_slope), w.f64(k.next_left_slope);
    w.u8(k.weighted_right), w.u8(k.weighted_next_left);
    w.f64(k.right_weight), w.f64(k.next_left_weight);
    w.u8(k.velocity_right), w.u8(k.velocity_next_left);
    w.f64(k.right_velocity), w.f64(k.next_left_velocity);
    w.f64(k.tension), w.f64(k.continuity), w.f64(k.bias);
  }
}
void get(Reader& r, FbxCurve& c) {
  c.node = r.str();
  c.property = r.str();
  c.channel = static_cast<char>(r.u8());
  if (c.channel != 'X' && c.channel != 'Y' && c.channel != 'Z' && c.channel != ' ') r.fail();  // ' ': a layer's weight
  c.layer = r.size();
  c.default_value = r.f64();
  for (FbxExtrapolationRule* e : {&c.pre, &c.post}) {
    e->mode = r.enumerator(FbxExtrapolation::keep_slope);
    const std::int64_t reps = r.i64();
    if (reps < -1 || reps > std::numeric_limits<int>::max()) r.fail();
    e->repetitions = static_cast<int>(reps);
  }
  c.keys.resize(r.count(kKey));
  for (std::size_t i = 0; i < c.keys.size(); ++i) {
    FbxKey& k = c.keys[i];
    k.ticks = r.i64();
    k.value = r.f64();
    k.interpolation = r.enumerator(FbxInterpolation::cubic);
    k.tangent = r.enumerator(FbxTangent::tcb);
    const std::uint64_t flags = r.u64();
    if (flags > std::numeric_limits<std::uint32_t>::max()) r.fail();
    k.flags = static_cast<std::uint32_t>(flags);
    k.right_slope = r.f64(), k.next_left_slope = r.f64();
    k.weighted_right = r.flag(), k.weighted_next_left = r.flag();
    k.right_weight = r.f64(), k.next_left_weight = r.f64();
    k.velocity_right = r.flag(), k.velocity_next_left = r.flag();
    k.right_velocity = r.f64(), k.next_left_velocity = r.f64();
    k.tension = r.f64(), k.continuity = r.f64(), k.bias = r.f64();
    // The evaluator relies on finite values and increasing times (rules of fbx_curves.h).
    for (double v : {k.value, k.right_slope, k.next_left_slope, k.right_weight, k.next_left_weight, k.tension,
                     k.continuity, k.bias})
      if (!std::isfinite(v)) r.fail();
    if (i > 0 && k.ticks <= c.keys[i - 1].ticks) r.fail();
  }
}

void put(Writer& w, const FbxAnimation& a) {
  w.u64(a.takes.size());
  for (const FbxTake& t : a.takes) {
    w.str(t.name);
    w.i64(t.start), w.i64(t.stop);
    w.u64(t.layers.size());
    for (const FbxLayer& l : t.layers) {
      w.str(l.name);
      w.f64(l.weight);
      w.u8(static_cast<std::uint8_t>(l.blend));
      w.u8(l.mute), w.u8(l.solo);
      w.i64(l.rotation_accumulation), w.i64(l.scale_accumulation);
      w.u8(l.weight_curve.has_value());
      if (l.weight_curve) put(w, *l.weight_curve);
    }
    w.u64(t.curves.size());
    for (const FbxCurve& c : t.curves) put(w, c);
    w.u64(t.properties.size());
    for (const FbxAnimatedProperty& p : t.properties) {
      w.str(p.node), w.str(p.property);
      w.u64(p.layer);
      put(w, p.defaults);
    }
  }
  w.u64(a.version);
  w.u64(a.models.size());
  for (const FbxModel& m : a.models) {
    w.str(m.name), w.str(m.type);
    w.i64(m.id), w.i64(m.parent);
    w.i64(m.rotation_order), w.i64(m.inherit_type);
    w.u8(m.rotation_active);
    for (const FbxVec3* v : {&m.translation, &m.rotation, &m.scaling, &m.pre_rotation, &m.post_rotation,
                             &m.rotation_offset, &m.rotation_pivot, &m.scaling_offset, &m.scaling_pivot})
      put(w, *v);
  }
}
void get(Reader& r, FbxAnimation& a) {
  a.takes.resize(r.count(kString + 8 + 8 + 8 + 8));
  for (FbxTake& t : a.takes) {
    t.name = r.str();
    t.start = r.i64(), t.stop = r.i64();
    t.layers.resize(r.count(kString + kDouble + 3 + 16 + 1));
    for (FbxLayer& l : t.layers) {
      l.name = r.str();
      l.weight = r.f64();
      l.blend = r.enumerator(FbxBlendMode::override_passthrough);
      l.mute = r.flag(), l.solo = r.flag();
      l.rotation_accumulation = r.index(), l.scale_accumulation = r.index();
      if (r.flag()) get(r, l.weight_curve.emplace());
    }
    t.curves.resize(r.count(2 * kString + 1 + 8 + kDouble + 18 + 8));
    for (FbxCurve& c : t.curves) {
      get(r, c);
      if (c.layer >= t.layers.size()) r.fail();
    }
    t.properties.resize(r.count(2 * kString + 8 + kFbxVec3));
    for (FbxAnimatedProperty& p : t.properties) {
      p.node = r.str(), p.property = r.str();
      p.layer = r.size();
      if (p.layer >= t.layers.size()) r.fail();
      get(r, p.defaults);
    }
  }
  a.version = static_cast<std::uint32_t>(r.size());
  a.models.resize(r.count(2 * kString + 4 * 8 + 1 + 9 * kFbxVec3));
  for (FbxModel& m : a.models) {
    m.name = r.str(), m.type = r.str();
    m.id = r.i64(), m.parent = r.i64();
    m.rotation_order = r.index(), m.inherit_type = r.index();
    if (m.rotation_order < 0 || m.rotation_order > 5) r.fail();
    m.rotation_active = r.flag();
    for (FbxVec3* v : {&m.translation, &m.rotation, &m.scaling, &m.pre_rotation, &m.post_rotation,
                       &m.rotation_offset, &m.rotation_pivot, &m.scaling_offset, &m.scaling_pivot})
      get(r, *v);
  }
}

}  // namespace

std::string encode(const ReadOutcome& outcome) {
  Writer w;
  w.raw(kMagic.data(), kMagic.size());
  w.u8(outcome.error.has_value());
  if (outcome.error) {
    w.str(*outcome.error);
    w.u8(static_cast<std::uint8_t>(outcome.kind));
  }
  const ClipFileInfo& info = outcome.info;
  w.str(info.format);
  w.u64(info.animations.size());
  for (const AnimationSummary& a : info.animations) {
    w.str(a.name);
    w.f64(a.duration);
    w.f64(a.ticks_per_second);
    w.u8(a.default_rate);
    w.u64(a.channels);
    w.f64(a.start);
    w.u64(a.keys);
    w.f64(a.frame_rate_hz);
    w.u8(a.rate_stated);
  }
  w.u64(info.selected);
  put(w, info.clip);
  w.u64(info.warnings.size());
  for (const std::string& s : info.warnings) w.str(s);
  w.u64(info.folded_helpers);
  w.u8(info.curves.has_value());
  if (info.curves) put(w, *info.curves);
  w.u8(info.body.has_value());
  if (info.body) put(w, *info.body);
  w.str(info.holds);
  return w.take();
}

Result<ReadOutcome> decode(std::string_view bytes) {
  if (bytes.substr(0, kMagic.size()) != kMagic) return make_error("not a rotinterp clip record");
  Reader r(bytes.substr(kMagic.size()));
  ReadOutcome out;
  if (r.flag()) {
    out.error = r.str();
    const std::uint8_t kind = r.u8();
    if (!sendable_kind(kind)) r.fail();
    out.kind = static_cast<ErrorKind>(kind);
  }
  ClipFileInfo& info = out.info;
  info.format = r.str();
  info.animations.resize(r.count(kString + 4 * kDouble + 2 + 2 * 8));
  for (AnimationSummary& a : info.animations) {
    a.name = r.str();
    a.duration = r.f64();
    a.ticks_per_second = r.f64();
    a.default_rate = r.flag();
    a.channels = r.size();
    a.start = r.f64();
    a.keys = r.size();
    a.frame_rate_hz = r.f64();
    a.rate_stated = r.flag();
  }
  info.selected = r.size();
  get(r, info.clip);
  info.warnings.resize(r.count(kString));
  for (std::string& s : info.warnings) s = r.str();
  info.folded_helpers = r.size();
  if (r.flag()) get(r, info.curves.emplace());
  if (r.flag()) get(r, info.body.emplace());
  info.holds = r.str();
  if (r.failed()) return make_error("clip record cut short or garbled");
  if (!r.at_end()) return make_error("clip record followed by stray bytes");
  return out;
}

}  // namespace rotinterp::wire
