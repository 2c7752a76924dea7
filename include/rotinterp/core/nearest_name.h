// The nearest of a few names to a misspelled one ("did you mean …?"), for the one
// suggestion every name lookup gives: methods, subcommands, options.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace rotinterp {

// Levenshtein distance, ignoring ASCII case (names are a few characters: O(|a|·|b|)).
std::size_t edit_distance(std::string_view a, std::string_view b);

// The candidate nearest `name` by edit_distance (the first of equals), given only when
// it is within a third of the name's length, at least 2 edits; else nullopt.
std::optional<std::string> nearest_name(std::string_view name, const std::vector<std::string>& candidates);

}  // namespace rotinterp
