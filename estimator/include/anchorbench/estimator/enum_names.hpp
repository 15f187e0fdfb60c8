#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <string_view>
#include <utility>

namespace anchorbench::estimator {

// An enum's names, each value once, in the order a config lists its choices: ToString and Parse
// of every enum read such a table, and the config reader lists the choices from it.
template <typename Enum, std::size_t N>
class EnumNames {
 public:
  using Entry = std::pair<Enum, std::string_view>;
  constexpr explicit EnumNames(const Entry (&entries)[N]) {
    for (std::size_t i = 0; i < N; ++i) entries_[i] = entries[i];
  }

  constexpr std::string_view Name(Enum value) const {
    for (const Entry& entry : entries_) {
      if (entry.first == value) return entry.second;
    }
    return "unknown";
  }
  // False, leaving *value as it is, for a name not in the table.
  constexpr bool Parse(std::string_view name, Enum* value) const {
    for (const Entry& entry : entries_) {
      if (entry.second == name) {
        *value = entry.first;
        return true;
      }
    }
    return false;
  }
  std::string Choices() const {  // "a, b, c"
    std::string choices;
    for (const Entry& entry : entries_) choices += (choices.empty() ? "" : ", ") + std::string(entry.second);
    return choices;
  }

 private:
  std::array<Entry, N> entries_{};
};

}  // namespace anchorbench::estimator
