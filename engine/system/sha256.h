#pragma once
// SHA-256 of a byte string (OpenSSL's libcrypto), as 64 lowercase hex digits: the content hash a
// report keeps of every plugin it ran (engine/plan/plugins.h), so a resumed sweep knows the same
// code runs.

#include <string>
#include <string_view>

namespace agv {

std::string sha256_hex(std::string_view bytes);

}  // namespace agv
