// BVH text straight into a clip (read_bvh_text): every data row parsed into one row
// of doubles and turned into its frame's keys at once, with no table of values.
#include "bvh_clip.h"
#include "bvh_text.h"

#include <cstddef>
#include <string>

namespace rotinterp {

using namespace bvh_text;
using namespace bvh_clip;

Result<StreamedBvh> read_bvh_text(std::string_view text, const std::string& label, const std::string& name,
                                  unsigned threads) {
  BvhFile header;  // everything but the values
  const Result<RowCursor> rows = read_to_rows(text, label, header);
  if (!rows) return rows.failure();
  const RowParser parser(header, label);
  if (header.frames > max_rows(*rows, header.columns)) {
    // The text cannot hold the declared frames: no clip to allocate, only the
    // first error in file order to find.
    std::size_t extra_rows = 0;
    const Status s = read_rows(*rows, 0, header.frames, parser, [](std::size_t, const double*) {}, extra_rows);
    ROTINTERP_ASSERT(!s);
    if (!s) return s.failure();
  }
  StreamedBvh out{empty_clip(header, name, header.frames), 0};
  const RowToKeys to_keys(header);
  // Each half: its rows found (the second half passes over the first's lines
  // unread, while the first half is parsed), parsed, converted.
  Status status[2] = {Ok{}, Ok{}};
  std::size_t extra_rows[2] = {0, 0};
  auto half = [&](std::size_t f0, std::size_t f1) {
    const int h = f0 > 0 ? 1 : 0;
    RowCursor c = *rows;
    if (skip_rows(c, f0) < f0) return;  // the file ends in the first half, whose pass says so
    auto convert = [&](std::size_t f, const double* row) { to_keys(row, f, f == f0, out.clip); };
    status[h] = read_rows(c, f0, f1, parser, convert, extra_rows[h]);
  };
  const std::size_t split =
      run_in_halves(header.frames, worth_two_threads(header.frames, header.columns, threads), half);
  // An error of the first half comes first in the file.
  for (const Status& s : status)
    if (!s) return s.failure();
  join_halves(out.clip, split);
  out.extra_rows = extra_rows[0] + extra_rows[1];
  return out;
}

}  // namespace rotinterp
