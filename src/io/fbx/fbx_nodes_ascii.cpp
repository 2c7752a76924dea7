// parse_fbx_ascii: ASCII FBX (6.1 and 7.x) into an FbxDocument: `Name: props {`
// children `}`, `;` comments, arrays as `*N { a: … }`, properties continued over
// lines after a comma.
#include "rotinterp/io/fbx/fbx_nodes.h"
#include "rotinterp/io/files/file_errors.h"

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <cstring>

namespace rotinterp {

namespace {

class AsciiReader {
 public:
  AsciiReader(std::string_view text, const std::string& label) : s_(text), label_(label) {}

  // Nodes until the end (depth 0) or a closing brace (consumed).
  Status nodes(std::vector<FbxNode>& out, std::size_t depth) {
    if (depth > kFbxMaxDepth) return fail("nested deeper than " + std::to_string(kFbxMaxDepth) + " levels");
    for (;;) {
      skip_blank(true);
      if (pos_ >= s_.size()) {
        if (depth > 0) return fail("missing '}' before the end of the file");
        return Ok{};
      }
      if (s_[pos_] == '}') {
        if (depth == 0) return fail("unmatched '}' on line " + std::to_string(line_));
        ++pos_;
        return Ok{};
      }
      FbxNode node;
      if (Status st = name(node.name); !st) return st;
      path_.push_back(node.name);
      if (Status st = properties(node, depth); !st) return st;
      path_.pop_back();
      out.push_back(std::move(node));
    }
  }

  Status fail(const std::string& what) const {
    return make_error(fbx_node_where(label_, path_) + ": " + what, file_error::unreadable);
  }

 private:
  // Spaces, tabs, comments; newlines too when `newlines`.
  void skip_blank(bool newlines) {
    while (pos_ < s_.size()) {
      const char c = s_[pos_];
      if (c == ';') {
        while (pos_ < s_.size() && s_[pos_] != '\n') ++pos_;
      } else if (c == '\n' && newlines) {
        ++line_, ++pos_;
      } else if (c == ' ' || c == '\t' || c == '\r' || (c == '\n' && newlines)) {
        ++pos_;
      } else {
        return;
      }
    }
  }

  Status name(std::string& out) {
    const std::size_t from = pos_;
    while (pos_ < s_.size() && s_[pos_] != ':' && s_[pos_] != '\n' && s_[pos_] != '{' && s_[pos_] != '}') ++pos_;
    if (pos_ >= s_.size() || s_[pos_] != ':') return fail("expected 'Name:' on line " + std::to_string(line_));
    std::string_view n = s_.substr(from, pos_ - from);
    while (!n.empty() && std::isspace(static_cast<unsigned char>(n.back()))) n.remove_suffix(1);
    out.assign(n);
    ++pos_;
    return Ok{};
  }

  // The node's properties up to the end of its line (continued after a comma),
  // then its children when a '{' follows.
  Status properties(FbxNode& node, std::size_t depth) {
    bool after_comma = false;
    for (;;) {
      skip_blank(after_comma);
      if (pos_ >= s_.size() || s_[pos_] == '\n' || s_[pos_] == '}') return Ok{};
      const char c = s_[pos_];
      if (c == '{') {
        ++pos_;
        return nodes(node.children, depth + 1);
      }
      if (c == ',') {
        ++pos_;
        after_comma = true;
        continue;
      }
      after_comma = false;
      if (c == '*') {
        if (Status st = array(node); !st) return st;
        return Ok{};
      }
      FbxProperty p;
      if (Status st = value(p); !st) return st;
      node.properties.push_back(std::move(p));
    }
  }

  // One scalar: a quoted string, a number or a bare word.
  Status value(FbxProperty& p) {
    if (s_[pos_] == '"') {
      const std::size_t close = s_.find('"', pos_ + 1);
      if (close == std::string_view::npos) return fail("unterminated string on line " + std::to_string(line_));
      p.type = 'S';
      p.text.assign(s_.substr(pos_ + 1, close - pos_ - 1));
      for (char ch : p.text) line_ += ch == '\n';
      pos_ = close + 1;
      return Ok{};
    }
    const std::size_t from = pos_;
    while (pos_ < s_.size() && !std::strchr(",{}\n;\r \t", s_[pos_])) ++pos_;
    if (pos_ == from) return fail("unexpected '" + fbx_printable(s_.substr(pos_, 1)) + "' on line " + std::to_string(line_));
    const std::string_view tok = s_.substr(from, pos_ - from);
    if (number(tok, p)) return Ok{};
    p.type = 'S';
    p.text.assign(tok);
    return Ok{};
  }

  static bool number(std::string_view tok, FbxProperty& p) {
    const char* b = tok.data();
    const char* e = b + tok.size();
    std::int64_t i = 0;
    if (auto r = std::from_chars(b, e, i); r.ec == std::errc() && r.ptr == e) {
      p.type = 'L', p.integer = i;
      return true;
    }
    double d = 0;
    if (auto r = std::from_chars(b, e, d); r.ec == std::errc() && r.ptr == e) {
      p.type = 'D', p.number = d;
      return true;
    }
    return false;
  }

  // `*N { a: v, v, … }`: N values, all integers ('l') or not ('d').
  Status array(FbxNode& node) {
    ++pos_;
    const std::size_t from = pos_;
    while (pos_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[pos_]))) ++pos_;
    std::uint64_t count = 0;
    if (std::from_chars(s_.data() + from, s_.data() + pos_, count).ec != std::errc() || pos_ == from)
      return fail("bad array count on line " + std::to_string(line_));
    // Each value takes at least two characters ("0,", the last without its comma).
    if (Status s = check_declared_count(count, 2, s_.size() - pos_ + 1, kFbxMaxArrayElements,
                                        fbx_node_where(label_, path_) + ": line " + std::to_string(line_));
        !s)
      return s;
    skip_blank(true);
    if (pos_ >= s_.size() || s_[pos_] != '{') return fail("expected '{' after the array count");
    ++pos_;
    FbxProperty p;
    p.type = 'l';
    std::vector<FbxProperty> values;
    values.reserve(static_cast<std::size_t>(count));
    skip_blank(true);
    if (pos_ < s_.size() && s_[pos_] != '}') {
      std::string a;
      if (Status st = name(a); !st) return st;
      for (;;) {
        skip_blank(true);
        if (pos_ >= s_.size()) return fail("missing '}' after the array");
        if (s_[pos_] == '}') break;
        if (s_[pos_] == ',') { ++pos_; continue; }
        FbxProperty v;
        if (Status st = value(v); !st) return st;
        if (!v.is_number()) return fail("a non-number in an array on line " + std::to_string(line_));
        if (values.size() == count) return fail("more than the " + std::to_string(count) + " array values declared");
        if (v.type == 'D') p.type = 'd';
        values.push_back(v);
      }
    }
    ++pos_;
    if (values.size() != count)
      return fail("array declares " + std::to_string(count) + " values and holds " + std::to_string(values.size()));
    if (p.type == 'l')
      for (const FbxProperty& v : values) p.integers.push_back(v.integer);
    else
      for (const FbxProperty& v : values) p.numbers.push_back(v.as_double());
    node.properties.push_back(std::move(p));
    return Ok{};
  }

  std::string_view s_;
  const std::string& label_;
  std::size_t pos_ = 0;
  std::size_t line_ = 1;
  std::vector<std::string> path_;
};

// "; FBX 7.5.0 project file" → 7500; else FBXHeaderExtension/FBXVersion; else 0.
std::uint32_t ascii_version(std::string_view text, const FbxDocument& doc) {
  constexpr std::string_view kMark = "; FBX ";
  if (text.substr(0, kMark.size()) == kMark) {
    int major = 0, minor = 0, patch = 0;
    const char* p = text.data() + kMark.size();
    const char* e = text.data() + std::min<std::size_t>(text.size(), 64);
    auto r = std::from_chars(p, e, major);
    if (r.ec == std::errc() && r.ptr < e && *r.ptr == '.') {
      auto r2 = std::from_chars(r.ptr + 1, e, minor);
      if (r2.ec == std::errc() && r2.ptr < e && *r2.ptr == '.') std::from_chars(r2.ptr + 1, e, patch);
      if (major > 0 && major < 100 && minor >= 0 && minor < 10) return static_cast<std::uint32_t>(major * 1000 + minor * 100);
    }
  }
  if (const FbxNode* h = doc.node("FBXHeaderExtension"))
    if (const FbxNode* v = h->child("FBXVersion"); v && !v->properties.empty() && v->properties[0].is_integer())
      return static_cast<std::uint32_t>(v->properties[0].integer);
  return 0;
}

}  // namespace

Result<FbxDocument> parse_fbx_ascii(std::string_view text, const std::string& label) {
  if (text.find('\0') != std::string_view::npos)
    return make_error(label + ": not an FBX file (binary bytes without the binary FBX header)", file_error::unreadable);
  FbxDocument doc;
  AsciiReader reader(text, label);
  if (Status s = reader.nodes(doc.nodes, 0); !s) return s.failure();
  doc.version = ascii_version(text, doc);
  return doc;
}

}  // namespace rotinterp
