#include "engine/outputs/report_digest.h"

#include "core/input_error.h"
#include "core/json_text.h"
#include "engine/outputs/report.h"
#include "engine/system/sha256.h"

namespace agv {

std::string report_digest(const nlohmann::json& report, const std::string& name) {
  if (!report.is_object() || report.value("tool", nlohmann::json()) != "agvbench" ||
      !report.contains("config") || !report.contains("cells"))
    throw InputError(name + ": not an agvbench report (no \"tool\": \"agvbench\", config, cells)");
  // nlohmann's object is a std::map: keys come out sorted, so the text is canonical.
  return sha256_hex(json_text(deterministic_part(report)));
}

}  // namespace agv
