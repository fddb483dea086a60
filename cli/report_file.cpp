#include "cli/report_file.h"

#include "core/input_error.h"
#include "core/text_file.h"

namespace agv {

nlohmann::json read_report(const std::string& path, const std::string& what) {
  const std::string text = read_text_file(path, what);
  try {
    return nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& e) {
    throw InputError(what + " \"" + path + "\": malformed JSON (" + e.what() + ")");
  }
}

}  // namespace agv
