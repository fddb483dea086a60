#include "cli/option_checks.h"

#include <string>

#include "cli/cli_numbers.h"

namespace agv {

CLI::Validator integer_in(IntRange range) {
  return CLI::Validator(
      [range](std::string& text) { return cli_integer_error(text, range); },
      "INT in [" + std::to_string(range.lo) + ", " + std::to_string(range.hi) + "]");
}

CLI::Validator number_in(NumberRange range) {
  return CLI::Validator([range](std::string& text) { return cli_number_error(text, range); },
                        "NUMBER");
}

}  // namespace agv
