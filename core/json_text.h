#pragma once
// The one way a JSON document becomes text. Strings that came from the user's command line (a
// map file name, say) may hold bytes that are not UTF-8, which nlohmann's dump refuses with
// type_error 316 after all the work was done: such bytes are written as U+FFFD instead.

#include <nlohmann/json.hpp>
#include <string>

namespace agv {

inline std::string json_text(const nlohmann::json& document, int indent = -1) {
  return document.dump(indent, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace agv
