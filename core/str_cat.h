#pragma once
// A message from its parts, each written as operator<< writes it: the error texts of the map
// readers and generators.

#include <sstream>
#include <string>

namespace agv {

template <class... Parts>
std::string str_cat(const Parts&... parts) {
  std::ostringstream out;
  (out << ... << parts);
  return out.str();
}

}  // namespace agv
