#pragma once

#include <string>

#include <yaml-cpp/yaml.h>

namespace anchorbench::config {

// The one YAML document of a config's text (an empty text gives a null node). Throws schema::InputError
// naming source:line for a second document, a NUL byte, or text the YAML reader cannot step past;
// yaml-cpp's own exceptions (syntax, depth) pass through for the caller to word.
YAML::Node OnlyDocument(const std::string& text, const std::string& source);

}  // namespace anchorbench::config
