// JSON as every writer prints it. nlohmann refuses a string that is not valid UTF-8
// with an exception ("[json.exception.type_error.316] …") that would reach the user.
// Names are made valid before they go in (written_names.h); whatever else a document
// holds (a file's path, a reader's message) is printed with U+FFFD for each byte that
// is not valid UTF-8.
#pragma once

#include <nlohmann/json.hpp>

#include <string>

namespace rotinterp {

// `indent` as nlohmann's dump: −1 for one line.
inline std::string json_text(const nlohmann::json& document, int indent = -1) {
  return document.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace rotinterp
