// Text helpers shared by the assimp-facing sources (private to src/io).
#pragma once

#include <string>

namespace rotinterp {

// assimp's messages may span lines; errors and warnings are one line each.
inline std::string one_line(std::string s) {
  for (char& c : s)
    if (c == '\n' || c == '\r') c = ' ';
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

}  // namespace rotinterp
