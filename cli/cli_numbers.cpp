#include "cli/cli_numbers.h"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <system_error>

#include "core/input_error.h"

namespace agv {

namespace {

std::string in_quotes(const std::string& text) { return "\"" + text + "\""; }

template <class Range>
std::string bounds_text(Range range) {
  std::ostringstream out;
  out << "[" << range.lo << ", " << range.hi << "]";
  return out.str();
}

bool read_integer(const std::string& text, long long& value, bool& overflow) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  overflow = ec == std::errc::result_out_of_range;
  return ec == std::errc() && ptr == end && !text.empty();
}

// std::chars_format::general: decimal and exponent forms only (no hex, no leading '+'); "inf"
// and "nan" parse and are refused as not finite.
bool read_number(const std::string& text, double& value, bool& overflow) {
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value, std::chars_format::general);
  overflow = ec == std::errc::result_out_of_range;
  return ec == std::errc() && ptr == end && !text.empty();
}

}  // namespace

std::string cli_integer_error(std::string& text, IntRange range) {
  long long value = 0;
  bool overflow = false;
  if (!read_integer(text, value, overflow)) {
    if (overflow) return in_quotes(text) + " is outside " + bounds_text(range);
    return "expected an integer in " + bounds_text(range) + ", got " + in_quotes(text);
  }
  if (value < range.lo || value > range.hi) return text + " is outside " + bounds_text(range);
  text = std::to_string(value);
  return "";
}

std::string cli_number_error(std::string& text, NumberRange range) {
  double value = 0.0;
  bool overflow = false;
  if (!read_number(text, value, overflow)) {
    if (overflow) return in_quotes(text) + " is outside " + bounds_text(range);
    return "expected a number in " + bounds_text(range) + ", got " + in_quotes(text);
  }
  if (!std::isfinite(value))
    return in_quotes(text) + " is not a finite number (expected one in " + bounds_text(range) + ")";
  if (value < range.lo || value > range.hi) return text + " is outside " + bounds_text(range);
  char canonical[32];
  std::snprintf(canonical, sizeof canonical, "%.17g", value);
  text = canonical;
  return "";
}

long long parse_cli_integer(const std::string& text, const std::string& option, IntRange range) {
  std::string canonical = text;
  const std::string error = cli_integer_error(canonical, range);
  if (!error.empty()) throw InputError(option + ": " + error);
  long long value = 0;
  std::from_chars(canonical.data(), canonical.data() + canonical.size(), value);
  return value;
}

double parse_cli_number(const std::string& text, const std::string& option, NumberRange range) {
  std::string canonical = text;
  const std::string error = cli_number_error(canonical, range);
  if (!error.empty()) throw InputError(option + ": " + error);
  double value = 0.0;
  std::from_chars(canonical.data(), canonical.data() + canonical.size(), value,
                  std::chars_format::general);
  return value;
}

}  // namespace agv
