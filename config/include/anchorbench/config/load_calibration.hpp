#pragma once

#include <string>

#include "anchorbench/schema/calibration_spec.hpp"

namespace anchorbench::config {

// Reads and checks a calibration file (configs/calibrate_*.yaml; docs/calibration.md lists the
// keys); throws schema::InputError naming the file and key. Whether each parameter's key and bounds
// make a valid experiment is checked by the caller, which loads the experiment at the bounds.
schema::CalibrationSpec LoadCalibrationSpec(const std::string& path);

// The value of a dotted key ("scenario.tunnel.width_m") in an experiment's resolved YAML
// (ToYaml), as text; throws schema::InputError naming `what` if the key is not a number there.
double NumberAt(const std::string& resolved_yaml, const std::string& key, const std::string& what);

}  // namespace anchorbench::config
