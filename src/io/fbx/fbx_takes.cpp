// read_fbx_takes: FBX 6.1 animation — Objects/Model (Properties60) with parents
// from Connections, and Takes/Take/Model/Channel "Transform"/T|R|S/X|Y|Z keys
// decoded from the 6.1 key list.
#include "fbx_objects.h"
#include "rotinterp/io/files/key_checks.h"
#include "rotinterp/io/files/file_errors.h"

#include <algorithm>
#include <cmath>
#include <map>

namespace rotinterp::fbx {

namespace {

// The 7.x KeyAttrFlags a 6.1 key means (fbx_curves.cpp decodes the same bits).
constexpr std::uint32_t kConstant = 0x2, kLinear = 0x4, kCubic = 0x8, kConstantNext = 0x100;
constexpr std::uint32_t kTangentAuto = 0x100, kTangentTcb = 0x200, kTangentUser = 0x400, kTangentBreak = 0x800;
constexpr std::uint32_t kWeightedRight = 0x1000000, kWeightedNextLeft = 0x2000000;

// A 6.1 key list: per key the time and value, an interpolation letter (C constant,
// L linear, U cubic) and what that letter needs. Binary files store letters as
// 'C' chars, ASCII files as bare one-letter words.
class KeyList {
 public:
  explicit KeyList(const std::vector<FbxProperty>& values) : v_(values) {}
  std::size_t size() const { return v_.size(); }
  bool at_end() const { return i_ == v_.size(); }
  bool number(double& out) {
    if (i_ >= v_.size() || !v_[i_].is_number() || v_[i_].type == 'C') return false;
    out = v_[i_++].as_double();
    return std::isfinite(out);
  }
  bool ticks(std::int64_t& out) {
    if (i_ < v_.size() && v_[i_].is_integer() && v_[i_].type != 'C') return out = v_[i_++].integer, true;
    double d = 0.0;
    if (!number(d) || std::abs(d) > 9e18) return false;
    out = static_cast<std::int64_t>(std::llround(d));
    return true;
  }
  bool letter(char& out) {
    if (i_ >= v_.size()) return false;
    const FbxProperty& p = v_[i_];
    if (p.type == 'C')
      out = static_cast<char>(p.integer);
    else if (p.is_string() && p.text.size() == 1)
      out = p.text[0];
    else
      return false;
    ++i_;
    return true;
  }

 private:
  const std::vector<FbxProperty>& v_;
  std::size_t i_ = 0;
};

// One key after its time and value: the interpolation and its tangent data.
// Returns "" or what is wrong.
std::string decode_key(KeyList& list, FbxKey& k) {
  char mode = 0;
  if (!list.letter(mode)) return "no interpolation letter";
  if (mode == 'L') return k.flags = kLinear, k.interpolation = FbxInterpolation::linear, "";
  if (mode == 'C') {
    char which = 0;
    if (!list.letter(which)) return "a constant key without its 's' or 'n'";
    k.interpolation = which == 'n' ? FbxInterpolation::constant_next : FbxInterpolation::constant_previous;
    k.flags = kConstant | (which == 'n' ? kConstantNext : 0);
    return "";
  }
  if (mode != 'U') return std::string("unknown interpolation '") + fbx_printable(std::string(1, mode)) + "'";
  k.interpolation = FbxInterpolation::cubic;
  k.flags = kCubic;
  char tangent = 0;
  if (!list.letter(tangent)) return "a cubic key without its tangent mode";
  int weight_modes = 1;
  double skipped = 0.0;
  switch (tangent) {
    case 's':
    case 'b':  // user slopes (right, next key's left); 'b' broken
      if (!list.number(k.right_slope) || !list.number(k.next_left_slope)) return "a cubic key without its two slopes";
      k.tangent = tangent == 'b' ? FbxTangent::broken : FbxTangent::user;
      k.flags |= kTangentUser | (tangent == 'b' ? kTangentBreak : 0);
      break;
    case 'a':  // auto: slopes solved from the neighbours
      k.tangent = FbxTangent::auto_smooth;
      k.flags |= kTangentAuto;
      break;
    case 't':  // TCB: tension, continuity, bias; no weights
      if (!list.number(k.tension) || !list.number(k.continuity) || !list.number(k.bias))
        return "a TCB key without its three parameters";
      k.tangent = FbxTangent::tcb;
      k.flags |= kTangentTcb;
      weight_modes = 0;
      break;
    case 'p':  // two values of unknown meaning and two weight modes (seen in baked files): evaluated as auto
      if (!list.number(skipped) || !list.number(skipped)) return "a 'p' key without its two values";
      k.tangent = FbxTangent::auto_smooth;
      k.flags |= kTangentAuto;
      weight_modes = 2;
      break;
    default:
      return std::string("unknown tangent mode '") + fbx_printable(std::string(1, tangent)) + "'";
  }
  for (int w = 0; w < weight_modes; ++w) {
    char weights = 0;
    if (!list.letter(weights)) return "a cubic key without its weight mode";
    if (weights == 'a' || weights == 'r') {
      if (!list.number(k.right_weight)) return "a weighted key without its weight";
      k.weighted_right = true;
      k.flags |= kWeightedRight;
    }
    if (weights == 'a' || weights == 'l') {
      if (!list.number(k.next_left_weight)) return "a weighted key without its weight";
      k.weighted_next_left = true;
      k.flags |= kWeightedNextLeft;
    }
    if (weights != 'a' && weights != 'r' && weights != 'l' && weights != 'n' && weights != 'c')
      return std::string("unknown weight mode '") + fbx_printable(std::string(1, weights)) + "'";
  }
  return "";
}

// Channel X, Y or Z of a T/R/S group: its Default, KeyCount and Key list.
Status read_channel(const FbxNode& channel, FbxCurve& c, const std::string& where, std::vector<std::string>& repairs) {
  if (const FbxNode* d = channel.child("Default"); d && !d->properties.empty())
    c.default_value = d->properties[0].as_double();
  if (!std::isfinite(c.default_value)) c.default_value = 0.0;
  const FbxNode* key = channel.child("Key");
  if (!key) return Ok{};
  const FbxNode* count_node = channel.child("KeyCount");
  if (!count_node || count_node->properties.empty() || !count_node->properties[0].is_integer())
    return make_error(where + ": a Key list without its KeyCount", file_error::unreadable);
  const std::int64_t count = count_node->properties[0].integer;
  KeyList list(key->properties);
  // A key takes three values at least (time, value, letter).
  if (count < 0 || static_cast<std::uint64_t>(count) > list.size() / 3)
    return make_error(where + ": KeyCount " + std::to_string(count) + " is past the end of its " +
                          std::to_string(list.size()) + " values",
                      file_error::unreadable);
  c.keys.resize(static_cast<std::size_t>(count));
  for (std::size_t i = 0; i < c.keys.size(); ++i) {
    FbxKey& k = c.keys[i];
    const std::string at = where + ": key " + std::to_string(i) + " of " + std::to_string(count);
    if (!list.ticks(k.ticks) || !list.number(k.value))
      return make_error(at + ": no time and finite value (the list ends or holds something else)",
                        file_error::unreadable);
    if (const std::string wrong = decode_key(list, k); !wrong.empty())
      return make_error(at + ": " + wrong, file_error::unreadable);
  }
  if (!list.at_end())
    return make_error(where + ": values after the last of its " + std::to_string(count) + " keys",
                      file_error::unreadable);
  std::vector<double> times, values;
  for (const FbxKey& k : c.keys) times.push_back(static_cast<double>(k.ticks)), values.push_back(k.value);
  Result<std::vector<std::size_t>> repaired = check_keys(times, values, 1, where);
  if (!repaired) return repaired.failure();
  drop_keys(c.keys, *repaired, 1);
  if (!repaired->empty()) repairs.push_back(repaired_keys_warning(where, repaired->size()));
  return Ok{};
}

// A take's Model: its Channel "Transform" → T, R, S → X, Y, Z.
Status read_take_model(const FbxNode& model, const std::vector<FbxModel>& models, FbxTake& take,
                       std::vector<std::string>& repairs, const std::string& where) {
  const std::string name = object_name(model);
  const FbxNode* transform = nullptr;
  for (const FbxNode& c : model.children)
    if (c.name == "Channel" && !c.properties.empty() && c.properties[0].is_string() &&
        c.properties[0].text == "Transform")
      transform = &c;
  if (!transform) return Ok{};
  static const std::map<std::string, std::string> kGroups = {
      {"T", "Lcl Translation"}, {"R", "Lcl Rotation"}, {"S", "Lcl Scaling"}};
  for (const FbxNode& group : transform->children) {
    if (group.name != "Channel" || group.properties.empty() || !group.properties[0].is_string()) continue;
    const auto property = kGroups.find(group.properties[0].text);
    if (property == kGroups.end()) continue;
    FbxAnimatedProperty animated{name, property->second, 0, {}};
    const auto m = std::find_if(models.begin(), models.end(), [&](const FbxModel& x) { return x.name == name; });
    if (m != models.end())
      animated.defaults = property->second == "Lcl Translation" ? m->translation
                          : property->second == "Lcl Rotation"  ? m->rotation
                                                                : m->scaling;
    bool any = false;
    for (const FbxNode& axis : group.children) {
      if (axis.name != "Channel" || axis.properties.empty() || !axis.properties[0].is_string()) continue;
      const std::string& letter = axis.properties[0].text;
      if (letter.size() != 1 || letter[0] < 'X' || letter[0] > 'Z') continue;
      if (!axis.child("Key") && !axis.child("Default")) continue;
      any = true;
      FbxCurve c;
      c.node = name;
      c.property = property->second;
      c.channel = letter[0];
      c.default_value = animated.defaults[static_cast<std::size_t>(letter[0] - 'X')];
      const std::string path = where + "/Model '" + fbx_printable(name) + "'/Channel Transform/" +
                               group.properties[0].text + "/" + letter + "/Key";
      if (Status st = read_channel(axis, c, path, repairs); !st) return st;
      animated.defaults[static_cast<std::size_t>(letter[0] - 'X')] = c.default_value;
      if (!c.keys.empty()) take.curves.push_back(std::move(c));
    }
    if (any) take.properties.push_back(std::move(animated));
  }
  return Ok{};
}

std::vector<FbxModel> read_legacy_models(const FbxDocument& doc) {
  std::vector<FbxModel> models;
  std::map<std::string, std::int64_t> id_of;  // the Model node's full name ("joint1\0\1Model", "Model::joint1")
  if (const FbxNode* objects = doc.node("Objects"))
    for (const FbxNode& node : objects->children) {
      if (node.name != "Model" || node.properties.empty() || !node.properties[0].is_string()) continue;
      FbxModel m;
      m.id = static_cast<std::int64_t>(models.size()) + 1;
      read_model_properties(node, nullptr, m);
      id_of.emplace(node.properties[0].text, m.id);
      models.push_back(std::move(m));
    }
  if (const FbxNode* conns = doc.node("Connections"))
    for (const FbxNode& c : conns->children) {
      const auto& p = c.properties;
      if (c.name != "Connect" || p.size() < 3 || !p[0].is_string() || p[0].text != "OO" || !p[1].is_string() ||
          !p[2].is_string())
        continue;
      const auto child = id_of.find(p[1].text), parent = id_of.find(p[2].text);
      if (child != id_of.end() && parent != id_of.end() && child->second != parent->second)
        models[static_cast<std::size_t>(child->second - 1)].parent = parent->second;
    }
  return models;
}

}  // namespace

Result<FbxAnimation> read_fbx_takes(const FbxDocument& doc, const std::string& label) {
  FbxAnimation anim;
  anim.version = doc.version;
  anim.models = read_legacy_models(doc);
  const FbxNode* takes = doc.node("Takes");
  if (!takes) return anim;
  for (const FbxNode& node : takes->children) {
    if (node.name != "Take") continue;
    FbxTake take;
    take.name = object_name(node);
    take.layers.emplace_back().name = "BaseLayer";
    for (const char* span : {"ReferenceTime", "LocalTime"})
      if (const FbxNode* t = node.child(span);
          t && t->properties.size() >= 2 && t->properties[0].is_integer() && t->properties[1].is_integer())
        take.start = t->properties[0].integer, take.stop = t->properties[1].integer;
    const std::string where = label + ": FBX node Takes/Take '" + fbx_printable(take.name) + "'";
    for (const FbxNode& model : node.children)
      if (model.name == "Model")
        if (Status st = read_take_model(model, anim.models, take, anim.repairs, where); !st) return st.failure();
    anim.takes.push_back(std::move(take));
  }
  return anim;
}

}  // namespace rotinterp::fbx
