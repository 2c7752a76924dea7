// synth_truth: eval's analytic reference for clips written by `rotinterp synth`.
#include "rotinterp/eval/synth_truth.h"

#include "rotinterp/clip/synth_spec.h"

#include <memory>

namespace rotinterp {

Result<TruthFn> synth_truth(const std::string& clip_file, const Clip& clip) {
  auto motion = read_synth_spec(clip_file);
  if (!motion) return motion.failure("--truth: ");
  const Skeleton& s = motion->skeleton();
  if (s.joints.size() != clip.skeleton.joints.size())
    return make_error(clip_file + ": the clip has " + std::to_string(clip.skeleton.joints.size()) +
                      " joints, its synth spec " + std::to_string(s.joints.size()));
  for (std::size_t j = 0; j < s.joints.size(); ++j)
    if (s.joints[j].name != clip.skeleton.joints[j].name)
      return make_error(clip_file + ": joint " + std::to_string(j) + " is '" + clip.skeleton.joints[j].name +
                        "', its synth spec has '" + s.joints[j].name + "'");
  auto shared = std::make_shared<const SynthMotion>(std::move(*motion));
  return TruthFn([shared](double t, std::vector<Quat>& rotation, std::vector<Vec3>& translation) {
    shared->truth(t, rotation, translation);
  });
}

}  // namespace rotinterp
