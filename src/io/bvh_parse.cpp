// Our own pass over BVH text: HIERARCHY (layout), MOTION header (exact Frame Time)
// and every data row (validated, in double).
#include "rotinterp/io/bvh.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <thread>
#include <unordered_set>
#include <vector>

namespace rotinterp {

namespace {

bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v'; }

// Whitespace-separated tokens with line numbers.
class Tokenizer {
 public:
  explicit Tokenizer(std::string_view text) : text_(text) {}

  // Next token, or empty at the end of the text.
  std::string_view next() {
    skip_space();
    const std::size_t start = pos_;
    while (pos_ < text_.size() && !is_space(text_[pos_])) ++pos_;
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

 private:
  void skip_space() {
    while (pos_ < text_.size() && is_space(text_[pos_])) {
      if (text_[pos_] == '\n') ++line_;
      ++pos_;
    }
  }
  std::string_view text_;
  std::size_t pos_ = 0;
  int line_ = 1;
};

// A full-token double (no trailing garbage); accepts "nan"/"inf" so that the caller
// can name them.
bool parse_double(std::string_view token, double& out) {
  // Fast path for what BVH data rows hold: [-]digits[.digits], at most 15 digits.
  // The digits make an integer m < 10¹⁵ < 2⁵³ and the point a power 10ᵏ (k ≤ 15),
  // both exact doubles, so m / 10ᵏ is one correctly rounded division: the same
  // value std::from_chars gives (Clinger's fast path).
  {
    static constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    const char* p = token.data();
    const char* const end = p + token.size();
    const bool negative = p < end && *p == '-';
    if (negative) ++p;
    std::uint64_t m = 0;
    int digits = 0, decimals = 0;
    const char* const first = p;
    while (p < end && *p >= '0' && *p <= '9') m = m * 10 + static_cast<unsigned>(*p++ - '0'), ++digits;
    if (p > first && p < end && *p == '.') {
      ++p;
      while (p < end && *p >= '0' && *p <= '9') m = m * 10 + static_cast<unsigned>(*p++ - '0'), ++digits, ++decimals;
    }
    if (p == end && p > first && digits <= 15) {
      const double v = static_cast<double>(m) / kPow10[decimals];
      out = negative ? -v : v;
      return true;
    }
  }
  if (!token.empty() && token.front() == '+') token.remove_prefix(1);
  if (token.empty()) return false;
  const auto [ptr, ec] = std::from_chars(token.data(), token.data() + token.size(), out);
  return ec == std::errc() && ptr == token.data() + token.size();
}

bool parse_channel(std::string_view token, Channel& out) {
  static constexpr std::pair<const char*, Channel> kNames[] = {
      {"Xposition", Channel::Xposition}, {"Yposition", Channel::Yposition}, {"Zposition", Channel::Zposition},
      {"Xrotation", Channel::Xrotation}, {"Yrotation", Channel::Yrotation}, {"Zrotation", Channel::Zrotation}};
  for (const auto& [name, channel] : kNames) {
    if (token.size() != std::string_view(name).size()) continue;
    bool same = true;
    for (std::size_t i = 0; i < token.size() && same; ++i)
      same = std::tolower(static_cast<unsigned char>(token[i])) == std::tolower(static_cast<unsigned char>(name[i]));
    if (same) {
      out = channel;
      return true;
    }
  }
  return false;
}

bool is_rotation(Channel c) { return c == Channel::Xrotation || c == Channel::Yrotation || c == Channel::Zrotation; }
int axis_of(Channel c) { return static_cast<int>(c) % 3; }

// A token or name as messages quote it: at most kExcerptBytes bytes (cut at a
// UTF-8 character boundary), control bytes as \xNN, and the full size when cut, so
// a 100 MB token gives a short line.
constexpr std::size_t kExcerptBytes = 40;
std::string excerpt(std::string_view t) {
  std::size_t n = std::min(t.size(), kExcerptBytes);
  if (n < t.size())
    while (n > 0 && (static_cast<unsigned char>(t[n]) & 0xC0) == 0x80) --n;  // not inside a character
  std::string out;
  for (std::size_t i = 0; i < n; ++i) {
    const auto c = static_cast<unsigned char>(t[i]);
    if (c < 0x20 || c == 0x7F) {
      static constexpr char kHex[] = "0123456789abcdef";
      out += {'\\', 'x', kHex[c >> 4], kHex[c & 15]};
    } else {
      out += static_cast<char>(c);
    }
  }
  if (n < t.size()) out += "… (" + std::to_string(t.size()) + " bytes)";
  return out;
}

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
      Channel ch;
      if (!parse_channel(c, ch))
        return fail("line " + std::to_string(l) + ": joint '" + jname + "': unknown channel " + quoted(c));
      channels.push_back(ch);
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

Quat BvhFile::rotation(std::size_t frame, std::size_t joint) const {
  Quat q = Quat::Identity();
  const BvhJoint& j = joints[joint];
  for (std::size_t c = 0; c < j.channels.size(); ++c)
    if (is_rotation(j.channels[c]))
      q = q * Quat(Eigen::AngleAxisd(value(frame, joint, c) * (kPi / 180.0), Vec3::Unit(axis_of(j.channels[c]))));
  return q.normalized();
}

Vec3 BvhFile::translation(std::size_t frame, std::size_t joint) const {
  Vec3 t = joints[joint].offset;
  const BvhJoint& j = joints[joint];
  for (std::size_t c = 0; c < j.channels.size(); ++c)
    if (!is_rotation(j.channels[c])) t[axis_of(j.channels[c])] = value(frame, joint, c);
  return t;
}

bool BvhFile::has_position_channels(std::size_t joint) const {
  for (Channel c : joints[joint].channels)
    if (!is_rotation(c)) return true;
  return false;
}

Result<BvhFile> parse_bvh(std::string_view text, const std::string& label) {
  // Text encodings: a UTF-8 byte order mark is skipped; UTF-16 (a BOM, or the NUL
  // bytes of ASCII text in it) is named rather than quoted.
  if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
  if (text.substr(0, 2) == "\xFF\xFE" || text.substr(0, 2) == "\xFE\xFF" ||
      (text.size() >= 2 && (text[0] == '\0' || text[1] == '\0')))
    return make_error(label + ": the file is UTF-16 text; BVH is read as UTF-8 or ASCII");
  BvhFile file;
  HeaderParser header(text, label);
  if (Status s = header.parse_hierarchy(file); !s) return s.failure();
  if (Status s = header.parse_motion_header(file); !s) return s.failure();

  // Data rows: one frame per non-blank line, exactly `columns` values each.
  std::size_t pos = header.position();
  int line = header.line();
  // The rest of the Frame Time line must be blank.
  auto line_end = [&](std::size_t from) {
    const std::size_t e = text.find('\n', from);
    return e == std::string_view::npos ? text.size() : e;
  };
  {
    const std::size_t e = line_end(pos);
    for (std::size_t i = pos; i < e; ++i)
      if (!is_space(text[i]))
        return make_error(label + ": line " + std::to_string(line) + ": unexpected text after the Frame Time");
    pos = e;
  }
  // Reserve by what the text can hold, never by the declared count.
  const std::size_t max_rows_in_text = static_cast<std::size_t>(std::count(text.begin() + pos, text.end(), '\n')) + 1;
  file.values.reserve(std::min(file.frames, max_rows_in_text) * file.columns);

  // Which joint/channel owns each column, for messages.
  std::vector<std::pair<std::size_t, std::size_t>> owner(file.columns);
  for (std::size_t j = 0; j < file.joints.size(); ++j)
    for (std::size_t c = 0; c < file.joints[j].channels.size(); ++c) owner[file.joints[j].first_column + c] = {j, c};

  // Messages are built only on failure: this loop runs once per value (millions).
  auto where = [&](std::size_t frame, int line) {
    return label + ": frame " + std::to_string(frame) + " (line " + std::to_string(line) + ")";
  };
  auto what = [&](std::size_t column) {
    const auto [joint, channel] = owner[column];
    return "joint '" + excerpt(file.joints[joint].name) + "' " + channel_name(file.joints[joint].channels[channel]);
  };
  const char* const end = text.data() + text.size();
  const char* p = text.data() + pos;
  std::size_t frame = 0;
  while (p < end) {
    ++p;  // past '\n'
    ++line;
    // Values up to the end of the line; '\n' is the only line break.
    while (p < end && *p != '\n' && is_space(*p)) ++p;
    if (p == end || *p == '\n') continue;  // blank line
    if (frame == file.frames) {
      ++file.extra_rows;
      const void* nl = std::memchr(p, '\n', static_cast<std::size_t>(end - p));
      p = nl ? static_cast<const char*>(nl) : end;
      continue;
    }
    std::size_t n = 0;
    while (p < end && *p != '\n') {
      const char* q = p;
      while (q < end && !is_space(*q)) ++q;
      const std::string_view token(p, static_cast<std::size_t>(q - p));
      if (n >= file.columns)
        return make_error(where(frame, line) + ": more than the " + std::to_string(file.columns) +
                          " values the HIERARCHY declares");
      double v = 0.0;
      if (!parse_double(token, v))
        return make_error(where(frame, line) + ", " + what(n) + ": not a number: '" + excerpt(token) + "'");
      if (!std::isfinite(v))
        return make_error(where(frame, line) + ", " + what(n) + ": value is " + excerpt(token) + " (not finite)");
      file.values.push_back(v);
      ++n;
      p = q;
      while (p < end && *p != '\n' && is_space(*p)) ++p;
    }
    if (n != file.columns)
      return make_error(label + ": frame " + std::to_string(frame) + " (line " + std::to_string(line) + ") has " +
                        std::to_string(n) + " values, the HIERARCHY declares " + std::to_string(file.columns));
    ++frame;
  }
  if (frame < file.frames)
    return make_error(label + ": 'Frames: " + std::to_string(file.frames) + "' but the file has only " +
                      std::to_string(frame) + (frame == 1 ? " data row" : " data rows"));
  return file;
}

Skeleton bvh_skeleton(const BvhFile& file) {
  Skeleton s;
  for (const BvhJoint& j : file.joints) s.joints.push_back(Joint{j.name, j.parent, j.offset, Quat::Identity()});
  for (const BvhEndSite& e : file.end_sites)
    s.end_sites.push_back(EndSite{e.parent, e.offset, "EndSite_" + file.joints[static_cast<std::size_t>(e.parent)].name});
  return s;
}

BvhLayout bvh_layout(const BvhFile& file) {
  BvhLayout layout;
  for (const BvhJoint& j : file.joints) layout.channels.push_back(j.channels);
  layout.frame_time_text = file.frame_time_text;
  return layout;
}

namespace {

struct RotationLayout {
  std::vector<std::size_t> column;  // value column of each rotation channel, in order
  std::vector<int> axis;
};

// Frames [f0, f1) of every joint, row by row (the values are row-major: going
// joint by joint would stream the whole table once per joint). Each rotation is
// the product of the joint's rotation channels (as BvhFile::rotation), normalized
// and on the side of the previous frame's key within the range.
void convert_frames(const BvhFile& file, const std::vector<RotationLayout>& layouts, std::size_t f0, std::size_t f1,
                    Clip& clip) {
  const std::size_t n = file.joints.size();
  for (std::size_t f = f0; f < f1; ++f) {
    const double* row = file.values.data() + f * file.columns;
    for (std::size_t j = 0; j < n; ++j) {
      const RotationLayout& l = layouts[j];
      Quat q = Quat::Identity();
      for (std::size_t i = 0; i < l.column.size(); ++i) {
        const double half = 0.5 * (row[l.column[i]] * (kPi / 180.0));
        Quat a(std::cos(half), 0.0, 0.0, 0.0);
        a.vec()[l.axis[i]] = std::sin(half);
        q = q * a;
      }
      q.normalize();  // a product of unit quaternions: its norm is 1 up to round-off
      std::vector<Quat>& keys = clip.rotations[j].keys;
      if (f > f0 && q.dot(keys[f - 1]) < 0.0) q.coeffs() = -q.coeffs();
      keys[f] = q;
      if (clip.translations[j]) clip.translations[j]->keys[f] = file.translation(f, j);
    }
  }
}

}  // namespace

Clip bvh_to_clip(const BvhFile& file, const std::string& name) {
  Clip clip;
  clip.name = name;
  clip.skeleton = bvh_skeleton(file);
  clip.frame_time = file.frame_time;
  clip.bvh_layout = std::make_shared<const BvhLayout>(bvh_layout(file));
  clip.source_format = "bvh";
  const std::size_t n = file.joints.size();
  const std::size_t frames = file.frames;
  std::vector<double> times(frames);
  for (std::size_t f = 0; f < frames; ++f) times[f] = static_cast<double>(f) * file.frame_time;
  std::vector<RotationLayout> layouts(n);
  clip.rotations.resize(n);
  clip.translations.resize(n);
  for (std::size_t j = 0; j < n; ++j) {
    const BvhJoint& joint = file.joints[j];
    for (std::size_t c = 0; c < joint.channels.size(); ++c)
      if (is_rotation(joint.channels[c])) {
        layouts[j].column.push_back(joint.first_column + c);
        layouts[j].axis.push_back(axis_of(joint.channels[c]));
      }
    clip.rotations[j].times = times;
    clip.rotations[j].keys.resize(frames);
    if (file.has_position_channels(j)) clip.translations[j] = TranslationTrack{times, std::vector<Vec3>(frames)};
  }
  // Long files convert on two threads, each half of the frames (the work is
  // trigonometry and first-touch page faults of the new tracks).
  constexpr std::size_t kMinValuesForThreads = 200000;
  std::size_t split = frames;
  std::exception_ptr helper_error;  // e.g. bad_alloc, rethrown here for read_clip to report
  std::optional<std::thread> helper;
  if (file.values.size() >= kMinValuesForThreads && std::thread::hardware_concurrency() > 1) {
    split = frames / 2;
    try {
      helper.emplace([&] {
        try {
          convert_frames(file, layouts, split, frames, clip);
        } catch (...) {
          helper_error = std::current_exception();
        }
      });
    } catch (const std::system_error&) {
      split = frames;  // no thread available: this one does all the work
    }
  }
  try {
    convert_frames(file, layouts, 0, split, clip);
  } catch (...) {
    if (helper) helper->join();
    throw;
  }
  if (helper) helper->join();
  if (helper_error) std::rethrow_exception(helper_error);
  // The second half joins the first one's sign.
  if (split > 0 && split < frames)
    for (RotationTrack& r : clip.rotations)
      if (r.keys[split].dot(r.keys[split - 1]) < 0.0)
        for (std::size_t f = split; f < frames; ++f) r.keys[f].coeffs() = -r.keys[f].coeffs();
  return clip;
}

}  // namespace rotinterp
