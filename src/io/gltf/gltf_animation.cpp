// The animation of a clip as glTF samplers and channels, and the buffer they go in
// (gltf_document.h).
#include "gltf_document.h"

#include "rotinterp/clip/translation_curve.h"
#include "rotinterp/interp/gltf_cubic.h"
#include "rotinterp/io/files/key_times.h"
#include "rotinterp/io/files/little_endian.h"
#include "rotinterp/io/files/written_names.h"
#include "rotinterp/track/sample.h"

#include <cmath>

namespace rotinterp::gltf {

void put_float(std::string& out, double v) { put_le(out, bits(static_cast<float>(v))); }

int Builder::accessor(std::size_t start, std::size_t count, const char* type, nlohmann::json extra) {
  views.push_back({{"buffer", 0}, {"byteOffset", start}, {"byteLength", bin.size() - start}});
  nlohmann::json a = {{"bufferView", views.size() - 1}, {"componentType", kFloat}, {"count", count}, {"type", type}};
  a.update(extra);
  accessors.push_back(a);
  return static_cast<int>(accessors.size() - 1);
}

namespace {

// A sampler input: the times as floats, with their min and max.
int time_accessor(Builder& b, const std::vector<double>& times) {
  const std::size_t start = b.bin.size();
  float lo = INFINITY, hi = -INFINITY;
  for (double t : times) {
    put_float(b.bin, t);
    lo = std::min(lo, static_cast<float>(t));
    hi = std::max(hi, static_cast<float>(t));
  }
  return b.accessor(start, times.size(), "SCALAR", {{"min", {lo}}, {"max", {hi}}});
}

void put_vec4(std::string& bin, const Eigen::Vector4d& v) {
  for (int c = 0; c < 4; ++c) put_float(bin, v[c]);
}

// The samplers of one joint's own keys (GltfKeys::own_times): (input, output,
// interpolation) for its rotation and, if any, its translation.
struct OwnSampler {
  int input, output;
  const char* interpolation;
  const char* path;
};
Result<std::vector<OwnSampler>> own_samplers(Builder& b, const Clip& clip, std::size_t j, const GltfKeys& keys, double scale) {
  std::vector<OwnSampler> out;
  const RotationTrack& rt = clip.rotations[j];
  const int rin = time_accessor(b, rt.times);
  std::size_t start = b.bin.size();
  if (keys.cubic_rotations) {
    // Each key as (in-tangent, value, out-tangent); ours are one tangent per key.
    auto k = gltf_cubic_keys(rt);
    if (!k) return k.failure("joint '" + clip.skeleton.joints[j].name + "': ");
    for (std::size_t i = 0; i < k->keys.size(); ++i) {
      put_vec4(b.bin, k->tangents[i]);
      put_vec4(b.bin, k->keys[i].coeffs());
      put_vec4(b.bin, k->tangents[i]);
    }
    out.push_back({rin, b.accessor(start, 3 * k->keys.size(), "VEC4"), "CUBICSPLINE", "rotation"});
  } else {
    Quat previous = rt.keys.front();
    for (Quat q : rt.keys) {
      if (q.dot(previous) < 0) q.coeffs() = -q.coeffs();
      previous = q;
      put_vec4(b.bin, q.coeffs());
    }
    out.push_back({rin, b.accessor(start, rt.keys.size(), "VEC4"), "LINEAR", "rotation"});
  }
  if (const auto& tr = clip.translations[j]) {
    const int tin = tr->times == rt.times ? rin : time_accessor(b, tr->times);
    start = b.bin.size();
    auto put3 = [&](const Vec3& v) {
      for (int a = 0; a < 3; ++a) put_float(b.bin, v[a] * scale);
    };
    if (keys.cubic_translations) {
      const TranslationCurve curve(*tr, TranslationInterp::cubic);
      for (std::size_t i = 0; i < tr->keys.size(); ++i) {
        const Vec3 m = curve.tangents().empty() ? Vec3::Zero() : curve.tangents()[i];
        put3(m);
        put3(tr->keys[i]);
        put3(m);
      }
      out.push_back({tin, b.accessor(start, 3 * tr->keys.size(), "VEC3"), "CUBICSPLINE", "translation"});
    } else {
      for (const Vec3& v : tr->keys) put3(v);
      out.push_back({tin, b.accessor(start, tr->keys.size(), "VEC3"), "LINEAR", "translation"});
    }
  }
  return out;
}

// One animation: per joint its rotation sampler (and translation sampler), its
// samplers' accessors appended to the buffer in joint order.
}  // namespace

Result<nlohmann::json> animation(Builder& b, const Clip& clip, const GltfKeys& keys, const JointTargets& targets) {
  const std::vector<double> times = keys.own_times ? std::vector<double>{} : all_key_times(clip);
  const int input = keys.own_times ? -1 : time_accessor(b, times);
  nlohmann::json samplers = nlohmann::json::array(), channels = nlohmann::json::array();
  for (std::size_t j = 0; j < clip.skeleton.joints.size(); ++j) {
    if (targets.node[j] == JointTargets::kNone) continue;
    auto channel = [&](int output, const char* path, int in = -1, const char* interpolation = "LINEAR") {
      samplers.push_back({{"input", in < 0 ? input : in}, {"output", output}, {"interpolation", interpolation}});
      channels.push_back({{"sampler", samplers.size() - 1}, {"target", {{"node", targets.node[j]}, {"path", path}}}});
    };
    if (keys.own_times) {
      auto own = own_samplers(b, clip, j, keys, targets.translation_scale[j]);
      if (!own) return own.failure();
      for (const OwnSampler& o : *own) channel(o.output, o.path, o.input, o.interpolation);
      continue;
    }
    std::size_t start = b.bin.size();
    // Sign-continuous keys (the clip's tracks are): no reader takes the long way round.
    Quat previous = sample_rotation(clip.rotations[j], times.front());
    for (double t : times) {
      Quat q = sample_rotation(clip.rotations[j], t);
      if (q.dot(previous) < 0) q.coeffs() = -q.coeffs();
      previous = q;
      for (double c : {q.x(), q.y(), q.z(), q.w()}) put_float(b.bin, c);
    }
    channel(b.accessor(start, times.size(), "VEC4"), "rotation");
    if (const auto& tr = clip.translations[j]) {
      start = b.bin.size();
      for (double t : times) {
        const Vec3 v = sample_translation(*tr, t);
        for (int a = 0; a < 3; ++a) put_float(b.bin, v[a] * targets.translation_scale[j]);
      }
      channel(b.accessor(start, times.size(), "VEC3"), "translation");
    }
  }
  return nlohmann::json{{"name", clip.name.empty() ? std::string("clip") : readable_text(clip.name)}, {"samplers", samplers}, {"channels", channels}};
}

}  // namespace rotinterp::gltf
