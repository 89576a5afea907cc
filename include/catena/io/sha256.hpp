// SHA-256 (FIPS 180-4), for the case hash in reports: the same digest `sha256sum` prints.
#pragma once

#include <string>
#include <string_view>

namespace catena::io {

/// Lower-case hexadecimal SHA-256 digest of `data`.
std::string sha256_hex(std::string_view data);

}  // namespace catena::io
