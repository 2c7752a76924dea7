// The file record a clip carries: its operations and accessors.
#include "rotinterp/io/files/file_record.h"
#include "rotinterp/clip/synth.h"

#include <array>
#include <memory>
#include <string>
#include <utility>

namespace rotinterp {

double FileRecord::stated_rate_hz() const { return rate_hz; }

SourceRecordPtr FileRecord::retimed() const {
  auto out = std::make_shared<FileRecord>(*this);
  if (out->bvh_layout) out->bvh_layout->frame_time_text.clear();
  return out;
}

SourceRecordPtr FileRecord::cut(std::size_t frames) const {
  auto out = std::make_shared<FileRecord>(*this);
  if (out->bvh_layout && out->bvh_layout->source_angles) out->bvh_layout->source_first_frame += frames;
  return out;
}

SourceRecordPtr FileRecord::rebuilt() const {
  if (rate_hz <= 0.0) return nullptr;
  auto out = std::make_shared<FileRecord>();
  out->rate_hz = rate_hz;
  return out;
}

const FileRecord* file_record(const Clip& clip) { return dynamic_cast<const FileRecord*>(clip.source_record.get()); }

const BvhLayout* bvh_layout(const Clip& clip) {
  const FileRecord* record = file_record(clip);
  return record && record->bvh_layout ? &*record->bvh_layout : nullptr;
}

const std::string& frame_time_text(const Clip& clip) {
  static const std::string none;
  const BvhLayout* layout = bvh_layout(clip);
  return layout ? layout->frame_time_text : none;
}

const std::vector<Channel>& bvh_channels(const Clip& clip, std::size_t joint) {
  static const std::vector<Channel> none;
  const BvhLayout* layout = bvh_layout(clip);
  return layout && joint < layout->channels.size() ? layout->channels[joint] : none;
}

namespace {

// A copy of the clip's file record (a new one where it has none), to change and set.
std::shared_ptr<FileRecord> record_to_change(const Clip& clip) {
  const FileRecord* record = file_record(clip);
  return record ? std::make_shared<FileRecord>(*record) : std::make_shared<FileRecord>();
}

// The clip's record is `record`; none where it holds nothing.
void set_record(Clip& clip, std::shared_ptr<FileRecord> record) {
  if (record->rate_hz == 0.0 && !record->bvh_layout) record.reset();
  clip.source_record = std::move(record);
}

// The layout that keys each joint's rotation in `orders` (axes 0 x, 1 y, 2 z, the
// first outermost), roots' positions first.
BvhLayout bvh_layout_of_orders(const Skeleton& skeleton, const std::vector<std::array<int, 3>>& orders) {
  BvhLayout layout;
  for (std::size_t j = 0; j < skeleton.joints.size() && j < orders.size(); ++j) {
    std::vector<Channel>& channels = layout.channels.emplace_back();
    if (skeleton.joints[j].parent < 0) channels = {Channel::Xposition, Channel::Yposition, Channel::Zposition};
    for (int axis : orders[j]) channels.push_back(static_cast<Channel>(static_cast<int>(Channel::Xrotation) + axis));
  }
  return layout;
}

}  // namespace

void set_bvh_layout(Clip& clip, std::optional<BvhLayout> layout) {
  auto record = record_to_change(clip);
  record->bvh_layout = std::move(layout);
  set_record(clip, std::move(record));
}

void set_file_rate_hz(Clip& clip, double rate_hz) {
  auto record = record_to_change(clip);
  record->rate_hz = rate_hz;
  set_record(clip, std::move(record));
}

Result<Clip> make_synth_file_clip(const SynthOptions& options) {
  auto motion = make_synth_motion(options);
  if (!motion) return motion.failure();
  Clip clip = motion->sample(options.seconds, options.fps, std::string("synth_") + synth_kind_name(options.kind));
  set_bvh_layout(clip, bvh_layout_of_orders(motion->skeleton(), motion->rotation_orders()));
  return clip;
}

}  // namespace rotinterp
