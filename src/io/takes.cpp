// Several takes of one file (io/takes.h).
#include "rotinterp/io/takes.h"

#include <algorithm>
#include <cctype>

namespace rotinterp {

namespace {

bool all_digits(const std::string& s) {
  return !s.empty() && s.size() < 10 && std::all_of(s.begin(), s.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::vector<std::string> comma_items(const std::string& text) {
  std::vector<std::string> items;
  std::size_t from = 0;
  for (std::size_t at = text.find(','); ; at = text.find(',', from)) {
    std::string item = text.substr(from, at == std::string::npos ? std::string::npos : at - from);
    const auto not_space = [](char c) { return !std::isspace(static_cast<unsigned char>(c)); };
    item.erase(item.begin(), std::find_if(item.begin(), item.end(), not_space));
    item.erase(std::find_if(item.rbegin(), item.rend(), not_space).base(), item.end());
    items.push_back(item);
    if (at == std::string::npos) return items;
    from = at + 1;
  }
}

}  // namespace

bool names_several_takes(const std::string& anim) { return anim == kAllTakes || anim.find(',') != std::string::npos; }

Result<std::vector<TakeRef>> select_takes(const std::filesystem::path& path, const std::string& anim,
                                          const ReadOptions& options) {
  ReadOptions first = options;
  first.animation.clear();
  Result<ClipFileInfo> info = inspect_clip(path, first);
  if (!info) return info.failure();
  return choose_takes(info->animations, anim, path.string());
}

Result<std::vector<TakeRef>> choose_takes(const std::vector<AnimationSummary>& takes, const std::string& anim,
                                          const std::string& label) {
  std::vector<TakeRef> out;
  const auto add = [&](std::size_t a) {
    if (std::none_of(out.begin(), out.end(), [a](const TakeRef& t) { return t.index == a; }))
      out.push_back({a, takes[a].name});
  };
  const auto named = [&](const std::string& name) {
    return std::find_if(takes.begin(), takes.end(), [&](const AnimationSummary& s) { return s.name == name; });
  };
  if (anim.empty()) {
    add(0);  // the first, as ReadOptions::animation reads it
  } else if (anim == kAllTakes) {
    for (std::size_t a = 0; a < takes.size(); ++a) add(a);
  } else if (const auto whole = named(anim); whole != takes.end()) {
    add(static_cast<std::size_t>(whole - takes.begin()));
  } else {
    for (const std::string& item : comma_items(anim)) {
      if (const auto it = named(item); it != takes.end()) {
        add(static_cast<std::size_t>(it - takes.begin()));
      } else if (all_digits(item) && std::stoul(item) < takes.size()) {
        add(std::stoul(item));
      } else {
        std::string have;
        for (std::size_t a = 0; a < takes.size(); ++a) have += (a ? ", " : "") + std::to_string(a) + " '" + takes[a].name + "'";
        return make_error(label + ": --anim " + anim + ": no take '" + item + "' (the file has " + have + ")");
      }
    }
  }
  return out;
}

std::string take_file_part(const TakeRef& take) {
  std::string out;
  bool any = false;
  for (char c : take.name) {
    const bool keep = std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' || c == '_';
    out += keep && static_cast<unsigned char>(c) < 0x80 ? c : '_';
    any = any || std::isalnum(static_cast<unsigned char>(c)) || c == '-';
  }
  return any ? out : "take" + std::to_string(take.index);
}

std::string with_take_name(const std::string& pattern, const TakeRef& take) {
  std::string out = pattern;
  const std::string part = take_file_part(take);
  for (std::size_t at = out.find(kTakePlaceholder); at != std::string::npos;
       at = out.find(kTakePlaceholder, at + part.size()))
    out.replace(at, std::string(kTakePlaceholder).size(), part);
  return out;
}

}  // namespace rotinterp
