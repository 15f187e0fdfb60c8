#include "anchorbench/schema/sweep.hpp"

#include <algorithm>

#include <charconv>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "anchorbench/schema/input_error.hpp"

namespace anchorbench::schema {

namespace {

constexpr std::size_t kMaxValuesPerAxis = 10000;
// Every point's config is loaded and validated before the first trial, and its summaries are kept:
// 1e4 points take ~10 s and a few hundred MB before any work.
constexpr double kMaxGridPoints = 10000;

std::string Trim(const std::string& text) {
  const std::size_t first = text.find_first_not_of(" \t");
  const std::size_t last = text.find_last_not_of(" \t");
  return first == std::string::npos ? "" : text.substr(first, last - first + 1);
}

double Number(const std::string& key, const std::string& text) {
  double value = 0.0;
  const std::string trimmed = Trim(text);
  const auto [end, ec] = std::from_chars(trimmed.data(), trimmed.data() + trimmed.size(), value);
  if (trimmed.empty() || ec != std::errc() || end != trimmed.data() + trimmed.size() || !std::isfinite(value)) {
    throw InputError("sweep '" + key + "': '" + text + "' is not a number");
  }
  return value;
}

}  // namespace

SweepAxis ParseSweepAxis(const std::string& key, const std::string& values) {
  SweepAxis axis{key, {}};
  if (key.empty()) throw InputError("sweep: an axis needs a key, e.g. estimator.trigger.pdop_threshold=0.5,1,2");
  // A range only where the text starts like a number: names such as nlopt:LN_BOBYQA are values.
  const std::string first_part = Trim(values.substr(0, values.find(':')));
  const bool numeric_start = !first_part.empty() && (std::isdigit(static_cast<unsigned char>(first_part[0])) ||
                                                    first_part[0] == '-' || first_part[0] == '+' || first_part[0] == '.');
  if (values.find(':') != std::string::npos && numeric_start) {
    const std::size_t first = values.find(':');
    const std::size_t second = values.find(':', first + 1);
    if (second == std::string::npos || values.find(':', second + 1) != std::string::npos) {
      throw InputError("sweep '" + key + "': a range is START:STOP:STEP, got '" + values + "'");
    }
    const double start = Number(key, values.substr(0, first));
    const double stop = Number(key, values.substr(first + 1, second - first - 1));
    const double step = Number(key, values.substr(second + 1));
    if (!(step > 0.0) || stop < start) {
      throw InputError("sweep '" + key + "': a range needs STEP > 0 and STOP >= START, got '" + values + "'");
    }
    const double count = std::floor((stop - start) / step + 1e-9) + 1.0;
    if (count > kMaxValuesPerAxis) throw InputError("sweep '" + key + "': more than 10000 values");
    for (int i = 0; i < static_cast<int>(count); ++i) {
      char text[32];
      std::snprintf(text, sizeof(text), "%.12g", start + i * step);
      axis.values.emplace_back(text);
    }
    return axis;
  }
  for (std::size_t start = 0;;) {
    const std::size_t comma = values.find(',', start);
    const std::string value = Trim(values.substr(start, comma == std::string::npos ? std::string::npos : comma - start));
    if (value.empty()) throw InputError("sweep '" + key + "': empty value in '" + values + "'");
    axis.values.push_back(value);
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return axis;
}

SweepAxis ParseSweepAssignment(const std::string& assignment) {
  const std::size_t equals = assignment.find('=');
  if (equals == std::string::npos) {
    throw InputError("--set '" + assignment + "': expected KEY=VALUES, e.g. estimator.trigger.pdop_threshold=0.5,1,2");
  }
  return ParseSweepAxis(assignment.substr(0, equals), assignment.substr(equals + 1));
}

std::vector<SweepPoint> SweepGrid(const std::vector<SweepAxis>& axes) {
  double points = 1.0;
  for (const SweepAxis& axis : axes) points *= static_cast<double>(axis.values.size());
  if (points > kMaxGridPoints) {
    throw InputError("sweep: " + std::to_string(static_cast<long long>(std::min(points, 1e18))) +
                     " grid points; at most 10000 (split the sweep)");
  }
  std::vector<SweepPoint> grid{{}};
  for (const SweepAxis& axis : axes) {
    std::vector<SweepPoint> next;
    for (const SweepPoint& point : grid) {
      for (const std::string& value : axis.values) {
        next.push_back(point);
        next.back().values.push_back(value);
        next.back().overrides.push_back(axis.key + "=" + value);
      }
    }
    grid = std::move(next);
  }
  return grid;
}

std::vector<SweepAxis> SweepAxes(const std::vector<std::pair<std::string, std::string>>& from_config,
                                 const std::vector<std::string>& assignments) {
  std::vector<SweepAxis> axes;
  for (const auto& [key, values] : from_config) axes.push_back(ParseSweepAxis(key, values));
  for (const std::string& assignment : assignments) {
    SweepAxis axis = ParseSweepAssignment(assignment);
    auto same = std::find_if(axes.begin(), axes.end(), [&](const SweepAxis& a) { return a.key == axis.key; });
    if (same != axes.end()) {
      *same = std::move(axis);
    } else {
      axes.push_back(std::move(axis));
    }
  }
  return axes;
}

std::vector<std::string> DescribeAxes(const std::vector<SweepAxis>& axes) {
  std::vector<std::string> described;
  for (const SweepAxis& axis : axes) {
    std::string values;
    for (const std::string& v : axis.values) values += (values.empty() ? "" : ",") + v;
    described.push_back(axis.key + "=" + values);
  }
  return described;
}

}  // namespace anchorbench::schema
