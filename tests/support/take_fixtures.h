// Multi-take FBX fixtures written as ASCII FBX text (no file copied from elsewhere):
// takes on one shared timeline whose curves hold every key of it, as 3ds Max and
// MotionBuilder export them, and keys off the frame grid.
#pragma once

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace rotinterp::test {

constexpr long long kFrameTicks = 1539538600;  // 1/30 s

struct TakeSpec {
  std::string name;
  int first_frame, last_frame;  // LocalStart, LocalStop; equal: none declared
};

// One bone whose T and R curves are given per frame time (seconds) at `key_times`;
// each take has its own layer, curve nodes and curves, all holding the same keys.
inline std::string fbx_text(const std::vector<TakeSpec>& takes, const std::vector<double>& key_times,
                     const std::function<double(int channel, double t)>& value, bool state_rate) {
  std::string objects = "\tModel: 1000, \"Model::Bone\", \"LimbNode\" {\n\t\tVersion: 232\n\t}\n";
  std::string links = "\tC: \"OO\",1000,0\n";
  long long id = 2000;
  std::string times;
  for (double t : key_times) times += (times.empty() ? "" : ",") + std::to_string(std::llround(t * 30.0 * kFrameTicks));
  for (const TakeSpec& take : takes) {
    const long long stack = id++, layer = id++;
    std::string span;
    if (take.first_frame != take.last_frame)
      span = "\t\tProperties70:  {\n\t\t\tP: \"LocalStart\", \"KTime\", \"Time\", \"\"," +
             std::to_string(take.first_frame * kFrameTicks) + "\n\t\t\tP: \"LocalStop\", \"KTime\", \"Time\", \"\"," +
             std::to_string(take.last_frame * kFrameTicks) + "\n\t\t}\n";
    objects += "\tAnimationStack: " + std::to_string(stack) + ", \"AnimStack::" + take.name + "\", \"\" {\n" + span + "\t}\n";
    objects += "\tAnimationLayer: " + std::to_string(layer) + ", \"AnimLayer::Base\", \"\" {\n\t}\n";
    links += "\tC: \"OO\"," + std::to_string(layer) + "," + std::to_string(stack) + "\n";
    for (int property = 0; property < 2; ++property) {
      const long long node = id++;
      objects += "\tAnimationCurveNode: " + std::to_string(node) + ", \"AnimCurveNode::" + (property ? "R" : "T") +
                 "\", \"\" {\n\t}\n";
      links += "\tC: \"OO\"," + std::to_string(node) + "," + std::to_string(layer) + "\n";
      links += "\tC: \"OP\"," + std::to_string(node) + ",1000, \"" + (property ? "Lcl Rotation" : "Lcl Translation") + "\"\n";
      for (int axis = 0; axis < 3; ++axis) {
        const long long curve = id++;
        std::string values;
        for (double t : key_times) values += (values.empty() ? "" : ",") + std::to_string(value(3 * property + axis, t));
        const std::string n = std::to_string(key_times.size());
        objects += "\tAnimationCurve: " + std::to_string(curve) + ", \"AnimCurve::\", \"\" {\n\t\tDefault: 0\n\t\tKeyVer: 4009\n" +
                   "\t\tKeyTime: *" + n + " {\n\t\t\ta: " + times + "\n\t\t}\n\t\tKeyValueFloat: *" + n +
                   " {\n\t\t\ta: " + values + "\n\t\t}\n\t}\n";
        links += "\tC: \"OP\"," + std::to_string(curve) + "," + std::to_string(node) + ", \"d|" + "XYZ"[axis] + "\"\n";
      }
    }
  }
  const std::string settings = state_rate ? "GlobalSettings:  {\n\tVersion: 1000\n\tProperties70:  {\n"
                                            "\t\tP: \"TimeMode\", \"enum\", \"\", \"\",6\n\t}\n}\n"
                                          : "";
  return "; FBX 7.4.0 project file\nFBXHeaderExtension:  {\n\tFBXHeaderVersion: 1003\n\tFBXVersion: 7400\n}\n" +
         settings + "Objects:  {\n" + objects + "}\nConnections:  {\n" + links + "}\n";
}

// A move along X over 0–0.667 s, along Y over 0.833–1.333 s, a 180° spin about Z
// over 1.5–2 s (holding between), keyed at every frame of the 2 s timeline.
inline double shared_timeline_value(int channel, double t) {
  const auto ramp = [](double t, double a, double b) { return std::clamp((t - a) / (b - a), 0.0, 1.0); };
  if (channel == 0) return 10.0 * ramp(t, 0.0, 20.0 / 30);
  if (channel == 1) return 10.0 * ramp(t, 25.0 / 30, 40.0 / 30);
  if (channel == 5) return 180.0 * ramp(t, 45.0 / 30, 2.0);
  return 0.0;
}

inline std::vector<double> every_frame(int last) {
  std::vector<double> t;
  for (int f = 0; f <= last; ++f) t.push_back(f / 30.0);
  return t;
}

// The three takes of shared_timeline_value on their 2 s timeline at 30 fps: 'anim 1'
// (frames 0–20), 'anim 2' (25–40), 'spin' (45–60).
inline std::string shared_timeline_fbx() {
  return fbx_text({{"anim 1", 0, 20}, {"anim 2", 25, 40}, {"spin", 45, 60}}, every_frame(60), shared_timeline_value, true);
}

}  // namespace rotinterp::test
