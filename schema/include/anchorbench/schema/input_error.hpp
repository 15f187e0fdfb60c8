#pragma once

#include <stdexcept>
#include <string>

namespace anchorbench::schema {

// Bad user input (a config key, a CSV line, a command-line value). The message names where:
// "FILE:LINE: ..." for CSV, "FILE: key 'a.b.c': ..." for YAML. The command line prints it once
// and exits with code 2.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace anchorbench::schema
