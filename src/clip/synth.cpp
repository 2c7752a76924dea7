// Synthetic motions known in closed form: the random kinds and the walking figure, and their clips.
#include "rotinterp/clip/synth.h"


#include <array>
#include <cmath>
#include <random>

namespace rotinterp {

namespace {

constexpr std::size_t kMaxSamples = 50000000;  // frames × joints: ~2 GB of keys

// Deterministic randomness: mt19937_64's sequence is fixed by the standard; the
// mapping to doubles is ours (library distributions differ between vendors).
class Random {
 public:
  explicit Random(std::uint64_t seed) : gen_(seed) {}
  double uniform() { return static_cast<double>(gen_() >> 11) * 0x1.0p-53; }  // [0, 1)
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  int below(int n) { return static_cast<int>(gen_() % static_cast<std::uint64_t>(n)); }
  Vec3 unit_vector() {
    for (;;) {
      const Vec3 v(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
      const double n = v.norm();
      if (n > 1e-3 && n <= 1.0) return v / n;
    }
  }
  Quat rotation() {  // uniform on SO(3) (Shoemake)
    const double u1 = uniform(), u2 = kTwoPi * uniform(), u3 = kTwoPi * uniform();
    const double a = std::sqrt(1.0 - u1), b = std::sqrt(u1);
    return Quat(a * std::cos(u2), a * std::sin(u2), b * std::sin(u3), b * std::cos(u3)).normalized();
  }

 private:
  std::mt19937_64 gen_;
};

const std::array<int, 3> kRotationOrders[6] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};

SynthMotion::RotationOrders random_orders(const Skeleton& s, Random& rng) {
  SynthMotion::RotationOrders orders;
  for (std::size_t j = 0; j < s.joints.size(); ++j) orders.push_back(kRotationOrders[rng.below(6)]);
  return orders;
}

VectorCurve axis_wave(const Vec3& axis, double bias, double amp, double omega, double phase) {
  VectorCurve c;
  c.c0 = axis * bias;
  if (amp != 0.0) c.waves.push_back({axis * amp, omega, phase});
  return c;
}

// A binary tree of `count` joints in depth-first order (as a BVH file lists them),
// random bone directions, End Sites on the leaves.
Skeleton tree_skeleton(int count, Random& rng) {
  // Heap-shaped tree (children of i: 2i+1, 2i+2), numbered in depth-first preorder.
  std::vector<int> order, stack{0};
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    order.push_back(i);
    for (int c : {2 * i + 2, 2 * i + 1})
      if (c < count) stack.push_back(c);
  }
  std::vector<int> index_of(static_cast<std::size_t>(count));
  for (int k = 0; k < count; ++k) index_of[static_cast<std::size_t>(order[static_cast<std::size_t>(k)])] = k;
  Skeleton s;
  for (int k = 0; k < count; ++k) {
    const int heap = order[static_cast<std::size_t>(k)];
    Joint j;
    j.name = k == 0 ? "Root" : "J" + std::to_string(k);
    j.parent = heap == 0 ? -1 : index_of[static_cast<std::size_t>((heap - 1) / 2)];
    if (k > 0) j.offset = rng.unit_vector() * rng.uniform(8.0, 15.0);
    s.joints.push_back(j);
  }
  for (int k = 0; k < count; ++k)
    if (2 * order[static_cast<std::size_t>(k)] + 1 >= count)
      s.end_sites.push_back({k, rng.unit_vector() * 5.0, "EndSite_" + s.joints[static_cast<std::size_t>(k)].name});
  return s;
}

SynthMotion random_motion(const SynthOptions& o, Random& rng) {
  Skeleton s = tree_skeleton(o.joints, rng);
  SynthMotion::RotationOrders orders = random_orders(s, rng);
  std::vector<JointMotion> m(s.joints.size());
  for (std::size_t j = 0; j < m.size(); ++j) {
    JointMotion& jm = m[j];
    jm.base = rng.rotation();
    VectorCurve v;
    switch (o.kind) {
      case SynthKind::constant:
        v.c1 = rng.unit_vector() * rng.uniform(0.5, 3.0);
        break;
      case SynthKind::smooth:
        for (int w = 0; w < 3; ++w)
          v.waves.push_back({rng.unit_vector() * rng.uniform(0.2, 0.5), kTwoPi * rng.uniform(0.2, 1.5), rng.uniform(0, kTwoPi)});
        break;
      case SynthKind::spin: {
        const Vec3 axis = rng.unit_vector();
        const double omega = kTwoPi * rng.uniform(1.0, 2.0);  // 1–2 turns/s
        const double mod = kTwoPi * 0.25;                     // speed varies ±30 % at 0.25 Hz
        v.c1 = axis * omega;
        v.waves.push_back({axis * (0.3 * omega / mod), mod, rng.uniform(0, kTwoPi)});
        // A small wobble about a perpendicular axis, applied after the spin.
        const Vec3 perp = axis.unitOrthogonal();
        jm.factors.push_back(axis_wave(perp, 0.0, 0.15, kTwoPi * rng.uniform(0.3, 0.8), rng.uniform(0, kTwoPi)));
        break;
      }
      case SynthKind::walk: break;
    }
    jm.factors.push_back(v);
  }
  VectorCurve root;
  root.c0 = Vec3(0.0, 90.0, 0.0);
  if (o.kind == SynthKind::smooth) {
    root.c1 = Vec3(0.0, 0.0, rng.uniform(30.0, 60.0));
    for (int w = 0; w < 2; ++w)
      root.waves.push_back({rng.unit_vector() * rng.uniform(5.0, 15.0), kTwoPi * rng.uniform(0.2, 1.0), rng.uniform(0, kTwoPi)});
  } else {
    const double heading = rng.uniform(0, kTwoPi);
    root.c1 = Vec3(std::cos(heading), 0.0, std::sin(heading)) * rng.uniform(50.0, 150.0);  // straight line
  }
  m[0].translation = root;
  return SynthMotion(std::move(s), std::move(m), std::move(orders));
}

// The walking figure: CMU's 31 joint names, a 1 Hz gait.
SynthMotion walk_motion(Random& rng) {
  struct Def {
    const char* name;
    int parent;
    Vec3 offset;
  };
  const Def defs[] = {
      {"Hips", -1, {0, 0, 0}},           {"LHipJoint", 0, {4, -3, 0}},      {"LeftUpLeg", 1, {5, -5, 0}},
      {"LeftLeg", 2, {0, -42, 0}},       {"LeftFoot", 3, {0, -42, 0}},      {"LeftToeBase", 4, {0, -6, 12}},
      {"RHipJoint", 0, {-4, -3, 0}},     {"RightUpLeg", 6, {-5, -5, 0}},    {"RightLeg", 7, {0, -42, 0}},
      {"RightFoot", 8, {0, -42, 0}},     {"RightToeBase", 9, {0, -6, 12}},  {"LowerBack", 0, {0, 8, 0}},
      {"Spine", 11, {0, 12, 0}},         {"Spine1", 12, {0, 12, 0}},        {"Neck", 13, {0, 14, 0}},
      {"Neck1", 14, {0, 5, 0}},          {"Head", 15, {0, 6, 0}},           {"LeftShoulder", 13, {3, 10, 0}},
      {"LeftArm", 17, {15, 0, 0}},       {"LeftForeArm", 18, {28, 0, 0}},   {"LeftHand", 19, {24, 0, 0}},
      {"LeftFingerBase", 20, {4, 0, 0}}, {"LeftHandIndex1", 21, {4, 0, 0}}, {"LThumb", 20, {2, 0, 3}},
      {"RightShoulder", 13, {-3, 10, 0}}, {"RightArm", 24, {-15, 0, 0}},  {"RightForeArm", 25, {-28, 0, 0}},
      {"RightHand", 26, {-24, 0, 0}},    {"RightFingerBase", 27, {-4, 0, 0}}, {"RightHandIndex1", 28, {-4, 0, 0}},
      {"RThumb", 27, {-2, 0, 3}}};
  Skeleton s;
  for (const Def& d : defs) {
    Joint j;
    j.name = d.name;
    j.parent = d.parent;
    j.offset = d.offset;
    s.joints.push_back(j);
  }
  s.end_sites = {{5, {0, 0, 5}, "EndSite_LeftToeBase"},  {10, {0, 0, 5}, "EndSite_RightToeBase"},
                 {16, {0, 10, 0}, "EndSite_Head"},        {22, {3, 0, 0}, "EndSite_LeftHandIndex1"},
                 {23, {2, 0, 2}, "EndSite_LThumb"},       {29, {-3, 0, 0}, "EndSite_RightHandIndex1"},
                 {30, {-2, 0, 2}, "EndSite_RThumb"}};
  SynthMotion::RotationOrders orders = random_orders(s, rng);

  const double f = rng.uniform(0.9, 1.1);  // gait frequency, Hz
  const double w = kTwoPi * f;
  auto jitter = [&rng](double a) { return a * rng.uniform(0.9, 1.1); };
  const Vec3 X = Vec3::UnitX(), Y = Vec3::UnitY(), Z = Vec3::UnitZ();
  std::vector<JointMotion> m(s.joints.size());
  auto add = [&](int j, const Vec3& axis, double bias, double amp, double omega, double phase) {
    m[static_cast<std::size_t>(j)].factors.push_back(axis_wave(axis, bias, jitter(amp), omega, phase));
  };
  // Pelvis: yaw with the stride, roll, pitch and bob at twice the stride.
  add(0, Y, 0.0, 0.12, w, 0.0);
  add(0, Z, 0.0, 0.06, w, kPi / 2);
  add(0, X, 0.0, 0.04, 2 * w, 0.0);
  VectorCurve root;
  root.c0 = Vec3(0.0, 95.0, 0.0);
  root.c1 = Vec3(0.0, 0.0, jitter(120.0) * f);
  root.waves = {{Vec3(0.0, 2.5, 0.0), 2 * w, 0.0}, {Vec3(1.5, 0.0, 0.0), w, 0.0}};
  m[0].translation = root;
  // Legs (right half a cycle later).
  for (int side = 0; side < 2; ++side) {
    const int b = side == 0 ? 1 : 6;
    const double ph = side == 0 ? 0.0 : kPi;
    add(b, Z, 0.0, 0.03, w, ph);                      // hip joint
    add(b + 1, X, -0.05, 0.45, w, ph + kPi);          // hip flexion (negative = forward)
    add(b + 1, Z, side == 0 ? 0.04 : -0.04, 0.03, w, ph);
    add(b + 2, X, 0.35, 0.35, w, ph + kPi / 2);       // knee, always bent backwards
    add(b + 3, X, 0.0, 0.2, w, ph + kPi / 3);         // ankle
    add(b + 4, X, 0.1, 0.15, w, ph + kPi / 4);        // toe
  }
  // Spine counter-rotates, head stabilizes.
  add(11, Y, 0.0, 0.06, w, kPi);
  add(11, X, 0.05, 0.02, 2 * w, 0.0);
  add(12, Y, 0.0, 0.05, w, kPi);
  add(13, Z, 0.0, 0.03, w, kPi / 2);
  add(14, Y, 0.0, 0.05, w, 0.0);
  add(15, X, 0.0, 0.03, 2 * w, kPi / 2);
  add(16, Y, 0.0, 0.04, w, 0.0);
  add(16, X, -0.05, 0.02, 2 * w, 0.0);
  // Arms: lowered from the T-pose, swinging against the legs; elbows flex.
  for (int side = 0; side < 2; ++side) {
    const int b = side == 0 ? 17 : 24;
    const double s_ = side == 0 ? 1.0 : -1.0;
    const double ph = side == 0 ? 0.0 : kPi;
    add(b, Z, 0.0, 0.03, 2 * w, ph);                             // shoulder
    add(b + 1, X, 0.0, 0.4, w, ph);                              // arm swing
    m[static_cast<std::size_t>(b + 1)].base = Quat(Eigen::AngleAxisd(-s_ * 1.25, Z));  // arm down
    add(b + 2, Y, -s_ * 0.35, 0.15, w, ph + kPi / 3);            // elbow
    add(b + 3, Z, 0.0, 0.1, w, ph);                              // wrist
    add(b + 4, Z, -s_ * 0.2, 0.05, w, ph);                       // finger base
    add(b + 5, Z, -s_ * 0.3, 0.05, w, ph + kPi / 2);             // index
    add(b + 6, Y, s_ * 0.3, 0.05, w, ph);                        // thumb
  }
  return SynthMotion(std::move(s), std::move(m), std::move(orders));
}

}  // namespace

const char* synth_kind_name(SynthKind k) {
  switch (k) {
    case SynthKind::constant: return "constant";
    case SynthKind::smooth: return "smooth";
    case SynthKind::spin: return "spin";
    case SynthKind::walk: return "walk";
  }
  return "?";
}

std::string synth_kind_names() { return "constant, smooth, spin, walk"; }

Result<SynthKind> parse_synth_kind(std::string_view name) {
  for (SynthKind k : {SynthKind::constant, SynthKind::smooth, SynthKind::spin, SynthKind::walk})
    if (name == synth_kind_name(k)) return k;
  return make_error("unknown synth kind '" + std::string(name) + "' (valid: " + synth_kind_names() + ")");
}

Result<SynthMotion> make_synth_motion(const SynthOptions& o) {
  if (!std::isfinite(o.seconds) || o.seconds <= 0.0) return make_error("synth: seconds must be greater than 0");
  if (o.fps.num <= 0 || o.fps.den <= 0) return make_error("synth: frame rate must be greater than 0");
  if (o.seconds * o.fps.hz() > 1e9) return make_error("synth: seconds × fps is too large");
  if (o.kind != SynthKind::walk && o.joints < 1) return make_error("synth: joints must be at least 1");
  const std::size_t joints = o.kind == SynthKind::walk ? 31 : static_cast<std::size_t>(o.joints);
  const std::size_t frames = sample_count(o.seconds, o.fps);
  if (frames > kMaxSamples / joints)
    return make_error("synth: " + std::to_string(frames) + " frames × " + std::to_string(joints) +
                      " joints is too large (at most " + std::to_string(kMaxSamples) + " keys)");
  Random rng(o.seed);
  return o.kind == SynthKind::walk ? walk_motion(rng) : random_motion(o, rng);
}

Result<Clip> make_synth_clip(const SynthOptions& o) {
  auto motion = make_synth_motion(o);
  if (!motion) return motion.failure();
  return motion->sample(o.seconds, o.fps, std::string("synth_") + synth_kind_name(o.kind));
}

}  // namespace rotinterp
