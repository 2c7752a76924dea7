// BVH text up to the data rows: the HIERARCHY section (joints, OFFSETs, CHANNELS,
// End Sites) and the MOTION header (Frames, exact Frame Time).
#include "bvh_text.h"
#include "rotinterp/io/files/file_errors.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

namespace rotinterp::bvh_text {

namespace {

// Whitespace-separated tokens with line numbers.
class Tokenizer {
 public:
  explicit Tokenizer(std::string_view text) : text_(text) {}

  // Next token, or empty at the end of the text.
  std::string_view next() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
    farthest_ = std::max(farthest_, pos_);
    return text_.substr(start, pos_ - start);
  }
  std::string_view peek() {
    const std::size_t p = pos_;
    const int l = line_;
    const std::string_view t = next();
    pos_ = p;
    line_ = l;
    return t;
  }
  int line() const { return line_; }
  // The line of the next token.
  int next_line() {
    skip_space();
    return line_;
  }
  std::size_t position() const { return pos_; }
  // How far any token reached: below the text's size, every token read ended in it.
  std::size_t farthest() const { return farthest_; }

 private:
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view text_;
  std::size_t pos_ = 0, farthest_ = 0;
  int line_ = 1;
};

class HeaderParser {
 public:
  HeaderParser(std::string_view text, const std::string& label) : tok_(text), label_(label) {}

  Status parse_hierarchy(BvhFile& file) {
    if (!expect("HIERARCHY")) return error_;
    bool any_root = false;
    while (true) {
      const std::string_view t = tok_.peek();
      if (t == "ROOT") {
        tok_.next();
        if (Status s = parse_tree(file); !s) return s;
        any_root = true;
      } else if (t == "MOTION") {
        break;
      } else {
        return fail("line " + std::to_string(tok_.next_line()) + ": expected ROOT or MOTION, found " + quoted(t));
      }
    }
    if (!any_root) return fail("the HIERARCHY section has no ROOT joint");
    return Ok{};
  }

  Status parse_motion_header(BvhFile& file) {
    if (!expect("MOTION")) return error_;
    // "Frames:" N (also "Frames:N")
    std::string_view t = tok_.next();
    std::string_view count_text;
    if (t == "Frames:") {
      count_text = tok_.next();
    } else if (t.substr(0, 7) == "Frames:") {
      count_text = t.substr(7);
    } else {
      return fail("line " + std::to_string(tok_.line()) + ": expected 'Frames:', found " + quoted(t));
    }
    double frames = 0.0;
    if (!parse_double(count_text, frames) || !std::isfinite(frames) || frames != std::floor(frames) || frames < 0)
      return fail("line " + std::to_string(tok_.line()) + ": 'Frames:' must be a whole number, found " +
                  quoted(count_text));
    if (frames < 1) return fail("'Frames: 0': the file has no motion");
    if (frames > 1e12) return fail("'Frames: " + excerpt(count_text) + "' is not a plausible frame count");
    file.frames = static_cast<std::size_t>(frames);
    // "Frame Time:" T (also "Frame Time:T")
    if (!expect("Frame")) return error_;
    t = tok_.next();
    std::string_view time_text;
    if (t == "Time:") {
      time_text = tok_.next();
    } else if (t.substr(0, 5) == "Time:") {
      time_text = t.substr(5);
    } else {
      return fail("line " + std::to_string(tok_.line()) + ": expected 'Frame Time:', found " + quoted(t));
    }
    double ft = 0.0;
    if (!parse_double(time_text, ft))
      return fail("line " + std::to_string(tok_.line()) + ": 'Frame Time:' is not a number: " + quoted(time_text));
    if (!std::isfinite(ft) || ft <= 0.0)
      return fail("'Frame Time: " + excerpt(time_text) + "' must be a positive number of seconds");
    if (ft < kMinBvhFrameTime || ft > kMaxBvhFrameTime)
      return fail("'Frame Time: " + excerpt(time_text) + "' is outside the accepted range " + number(kMinBvhFrameTime) +
                  " to " + number(kMaxBvhFrameTime) + " seconds");
    file.frame_time = ft;
    file.frame_time_text = std::string(time_text);
    return Ok{};
  }

  std::size_t position() const { return tok_.position(); }
  std::size_t farthest() const { return tok_.farthest(); }
  int line() const { return tok_.line(); }

 private:
  static std::string quoted(std::string_view t) { return t.empty() ? "the end of the file" : "'" + excerpt(t) + "'"; }
  static std::string number(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
  }

  Status fail(const std::string& what) {
    error_ = make_error(label_ + ": " + what);
    return error_;
  }

  bool expect(std::string_view word) {
    const int line = tok_.next_line();
    const std::string_view t = tok_.next();
    if (t == word) return true;
    (void)fail("line " + std::to_string(line) + ": expected '" + std::string(word) + "', found " + quoted(t));
    return false;
  }

  Status parse_vec3(Vec3& v, const std::string& what) {
    for (int i = 0; i < 3; ++i) {
      const int line = tok_.next_line();
      const std::string_view t = tok_.next();
      if (!parse_double(t, v[i]))
        return fail("line " + std::to_string(line) + ": " + what + ": expected a number, found " + quoted(t));
      if (!std::isfinite(v[i]))
        return fail("line " + std::to_string(line) + ": " + what + " is not finite (" + excerpt(t) + ")");
    }
    return Ok{};
  }

  // One ROOT and every joint below it, without recursion (a file may nest joints
  // as deep as it likes): `open` holds the joints whose '}' is still to come.
  Status parse_tree(BvhFile& file) {
    std::vector<int> open;
    if (Status s = open_joint(file, -1, open); !s) return s;
    while (!open.empty()) {
      const int index = open.back();
      const int l = tok_.next_line();
      const std::string_view t = tok_.next();
      if (t == "}") {
        open.pop_back();
      } else if (t == "JOINT") {
        if (open.size() >= kMaxJointDepth)
          return fail("line " + std::to_string(l) + ": joints nested more than " + std::to_string(kMaxJointDepth) +
                      " levels deep (the most rotinterp reads)");
        if (Status s = open_joint(file, index, open); !s) return s;
      } else if (t == "End") {
        const std::string what = "End Site OFFSET of joint '" + excerpt(file.joints[index].name) + "'";
        if (!expect("Site") || !expect("{") || !expect("OFFSET")) return error_;
        Vec3 e;
        if (Status s = parse_vec3(e, what); !s) return s;
        if (!expect("}")) return error_;
        file.end_sites.push_back(BvhEndSite{index, e});
      } else {
        return fail("line " + std::to_string(l) + ": joint '" + excerpt(file.joints[index].name) +
                    "': expected JOINT, End Site or '}', found " + quoted(t));
      }
    }
    return Ok{};
  }

  // A joint's name, '{', OFFSET and CHANNELS; the joint goes on `open`.
  Status open_joint(BvhFile& file, int parent, std::vector<int>& open) {
    const int line = tok_.next_line();
    const std::string_view name = tok_.next();
    if (name.empty() || name == "{") return fail("line " + std::to_string(line) + ": a joint has no name");
    if (name.size() > kMaxNameBytes)
      return fail("line " + std::to_string(line) + ": joint name '" + excerpt(name) + "' is longer than " +
                  std::to_string(kMaxNameBytes) + " bytes");
    if (!names_.insert(name).second)
      return fail("line " + std::to_string(line) + ": joint name '" + excerpt(name) + "' is used twice");
    const int index = static_cast<int>(file.joints.size());
    file.joints.push_back(BvhJoint{std::string(name), parent, Vec3::Zero(), {}, file.columns});
    open.push_back(index);
    const std::string jname = excerpt(name);
    if (!expect("{")) return error_;
    if (!expect("OFFSET")) return error_;
    if (Status s = parse_vec3(file.joints[index].offset, "OFFSET of joint '" + jname + "'"); !s) return s;
    // CHANNELS is optional for a joint in some writers (no channels).
    if (tok_.peek() != "CHANNELS") return Ok{};
    tok_.next();
    const int cl = tok_.next_line();
    const std::string_view n_text = tok_.next();
    double n = 0;
    if (!parse_double(n_text, n) || n < 0 || n > 64 || n != std::floor(n))
      return fail("line " + std::to_string(cl) + ": joint '" + jname + "': CHANNELS count " + quoted(n_text) +
                  " is not a small whole number");
    std::vector<Channel>& channels = file.joints[index].channels;
    for (int i = 0; i < static_cast<int>(n); ++i) {
      const int l = tok_.next_line();
      const std::string_view c = tok_.next();
      const std::optional<Channel> ch = channel_from_name(c);
      if (!ch) return fail("line " + std::to_string(l) + ": joint '" + jname + "': unknown channel " + quoted(c));
      channels.push_back(*ch);
    }
    file.columns += channels.size();
    return Ok{};
  }

  Tokenizer tok_;
  const std::string& label_;
  Status error_ = Ok{};
  std::unordered_set<std::string_view> names_;  // views into the text: one lookup per joint
};

}  // namespace

Result<DataStart> parse_header(std::string_view text, const std::string& label, BvhFile& file) {
  HeaderParser header(text, label);
  if (Status s = header.parse_hierarchy(file); !s) return s.failure();
  if (Status s = header.parse_motion_header(file); !s) return s.failure();
  return DataStart{header.position(), header.line()};
}

}  // namespace rotinterp::bvh_text

namespace rotinterp {

Status check_bvh_head(std::string_view head, bool whole_file, const std::string& label) {
  BvhFile file;
  bvh_text::HeaderParser header(head, label);
  Status s = header.parse_hierarchy(file);
  if (s) s = header.parse_motion_header(file);
  // A token that reached the head's end may go on in the file: only the full parse can tell.
  if (s || (!whole_file && header.farthest() >= head.size())) return Ok{};
  return make_error(s.error(), file_error::unreadable);
}

}  // namespace rotinterp
