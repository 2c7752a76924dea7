#include "rotinterp/io/files/kept_text.h"

namespace rotinterp {

std::string count_text(std::size_t n, const char* one, const char* many) {
  return std::to_string(n) + " " + (n == 1 ? one : many);
}

std::string kept_text(const std::vector<std::string>& parts) {
  std::string s;
  for (const std::string& p : parts) s += (s.empty() ? "" : ", ") + p;
  return s.empty() ? "the source's nodes kept (no mesh)" : s + " kept";
}

std::string unnormalized_weights_text(std::size_t vertices) {
  return count_text(vertices, "vertex's skin weights do", "vertices' skin weights do") + " not sum to 1";
}

}  // namespace rotinterp
