#pragma once
// Bad user input (a scenario, a raster, a species file, a command-line value). The program
// reports what() as one message and exits with code 2; anything else is an internal error.
#include <stdexcept>
#include <string>

namespace landsim {

class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace landsim
