#pragma once

#include <string>
#include <utility>
#include <vector>

namespace anchorbench::experiments {

// One sweep axis: a dotted config key and the values it takes, as text ("0.25", "symmetric").
struct SweepAxis {
  std::string key;
  std::vector<std::string> values;
};

// "0.5,1,2" is a list; "0.25:3:0.25" a range from 0.25 to 3 inclusive in steps of 0.25 (values
// printed with 12 significant digits, so 0.1 + 0.2 reads 0.3). Throws InputError naming the key.
SweepAxis ParseSweepAxis(const std::string& key, const std::string& values);
// "KEY=VALUES" from the command line.
SweepAxis ParseSweepAssignment(const std::string& assignment);

// Every combination of the axes' values, the first axis varying slowest; each point is the list
// of "KEY=VALUE" overrides that produce it.
std::vector<std::vector<std::string>> SweepGrid(const std::vector<SweepAxis>& axes);

}  // namespace anchorbench::experiments
