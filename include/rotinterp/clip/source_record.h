// What a reader keeps of its file that the clip model has no place for: the file's
// own layout and numbers, which only that format's writers read back, and the frame
// rate the file states apart from its keys. A Clip carries it without looking inside
// (Clip::source_record); io defines what is in it (io/files/file_record.h). A record
// is shared between copies and never changed: the clip operations that change what
// it describes (a new frame time, a cut, a rebuild) ask it for their result's record.
#pragma once

#include <cstddef>
#include <memory>

namespace rotinterp {

class SourceRecord {
 public:
  virtual ~SourceRecord() = default;
  // The frame rate the file states apart from its keys, Hz; 0 if none. resample's
  // default output rate when the keys lie on no grid.
  virtual double stated_rate_hz() const = 0;
  // The record of a copy whose frames are at another frame time.
  virtual std::shared_ptr<const SourceRecord> retimed() const = 0;
  // The record of a cut whose frame 0 is this record's clip's frame `frames`.
  virtual std::shared_ptr<const SourceRecord> cut(std::size_t frames) const = 0;
  // The record of a clip rebuilt from the description alone (Clip::without_tracks):
  // what holds whatever its frames; null when nothing does.
  virtual std::shared_ptr<const SourceRecord> rebuilt() const = 0;
};

using SourceRecordPtr = std::shared_ptr<const SourceRecord>;

// The same, for a record that may be null (null stays null).
inline double stated_rate_hz(const SourceRecordPtr& record) { return record ? record->stated_rate_hz() : 0.0; }
inline SourceRecordPtr retimed(const SourceRecordPtr& record) { return record ? record->retimed() : nullptr; }
inline SourceRecordPtr cut(const SourceRecordPtr& record, std::size_t frames) {
  return record ? record->cut(frames) : nullptr;
}
inline SourceRecordPtr rebuilt(const SourceRecordPtr& record) { return record ? record->rebuilt() : nullptr; }

}  // namespace rotinterp
