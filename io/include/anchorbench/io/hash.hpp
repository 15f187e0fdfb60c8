#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace anchorbench::io {

// FNV-1a, 64 bits: a stable fingerprint of a text (a resolved config), the same on every
// machine and build. Not cryptographic: it tells runs apart, it does not guard against forgery.
std::uint64_t Fnv1a64(std::string_view text);
// The same as 16 hex digits.
std::string Fingerprint(std::string_view text);

}  // namespace anchorbench::io
