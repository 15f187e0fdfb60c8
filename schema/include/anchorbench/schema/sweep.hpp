#pragma once

#include <string>
#include <utility>
#include <vector>

namespace anchorbench::schema {

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

// One grid point: the value of every axis, and the "KEY=VALUE" overrides that produce it.
struct SweepPoint {
  std::vector<std::string> values;  // one per axis, in axis order
  std::vector<std::string> overrides;
};

// Every combination of the axes' values, the first axis varying slowest.
std::vector<SweepPoint> SweepGrid(const std::vector<SweepAxis>& axes);

// The axes of a sweep: the config's own (key, values) pairs, then the command line's KEY=VALUES,
// which replace a config axis of the same key.
std::vector<SweepAxis> SweepAxes(const std::vector<std::pair<std::string, std::string>>& from_config,
                                 const std::vector<std::string>& assignments);

// "KEY=v1,v2,..." per axis, as the manifest records them.
std::vector<std::string> DescribeAxes(const std::vector<SweepAxis>& axes);

}  // namespace anchorbench::schema
