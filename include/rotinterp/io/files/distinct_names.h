// Joint names made distinct as a reader takes them (a Clip's names are unique; a
// file's may repeat or be empty); the writers' names go through it too, after
// written_names.h has made them safe to write.
#pragma once

#include <cstddef>
#include <string>
#include <unordered_map>
#include <unordered_set>

namespace rotinterp {

class DistinctNames {
 public:
  // `name` where no earlier call took it, else the first of name#, name#2, name#3, …
  // that is free. Linear over a file: 20 000 nodes of one name take milliseconds,
  // and a suffix stays a few digits long.
  std::string take(const std::string& name);

 private:
  std::unordered_set<std::string> taken_;
  std::unordered_map<std::string, std::size_t> next_suffix_;  // per repeated name: the suffix to try first
};

}  // namespace rotinterp
