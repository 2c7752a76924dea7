#include "rotinterp/io/files/source_method.h"

#include <algorithm>
#include <cctype>

namespace rotinterp {

bool is_source_method(const std::string& name) {
  const std::string want = kSourceMethodName;
  return name.size() == want.size() &&
         std::equal(name.begin(), name.end(), want.begin(),
                    [](char a, char b) { return std::tolower(static_cast<unsigned char>(a)) == b; });
}

}  // namespace rotinterp
