// `agvbench digest REPORT...`: each report's digest (engine/outputs/report_digest.h), one line each
// in sha256sum's layout, so that two machines' or two builds' results are compared by one line.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "cli/command.h"
#include "cli/report_file.h"
#include "engine/outputs/report_digest.h"

namespace agv {

namespace {

int command_digest(const std::vector<std::string>& paths) {
  // Every report is read and checked before a line is printed: one bad file, no partial list.
  std::vector<std::string> lines;
  for (const auto& path : paths) {
    const nlohmann::json report = read_report(path, "REPORT");
    lines.push_back(report_digest(report, "REPORT \"" + path + "\"") + "  " + path);
  }
  for (const auto& line : lines) std::cout << line << "\n";
  return 0;
}

}  // namespace

Command add_digest_command(CLI::App& app) {
  auto paths = std::make_shared<std::vector<std::string>>();
  auto* sub = app.add_subcommand(
      "digest", "SHA-256 of each report's non-timing part (what must agree between machines)");
  sub->add_option("reports", *paths, "sweep reports (JSON)")->required();
  return {sub, [paths] { return command_digest(*paths); }, false};
}

}  // namespace agv
