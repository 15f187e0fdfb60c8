#include "anchorbench/engine/shard.hpp"

#include <charconv>

#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::engine {

Shard ParseShard(const std::string& text, const std::string& what) {
  const std::size_t slash = text.find('/');
  Shard shard;
  const auto parse = [&](std::size_t begin, std::size_t end, int* value) {
    const auto [ptr, ec] = std::from_chars(text.data() + begin, text.data() + end, *value);
    return begin < end && ec == std::errc() && ptr == text.data() + end;
  };
  if (slash == std::string::npos || !parse(0, slash, &shard.index) || !parse(slash + 1, text.size(), &shard.count) ||
      shard.count < 1 || shard.count > 1000000 || shard.index < 0 || shard.index >= shard.count) {
    throw schema::InputError(what + ": '" + text + "' is not a shard I/N with 0 <= I < N <= 1000000 (e.g. 0/4)");
  }
  return shard;
}

}  // namespace anchorbench::engine
