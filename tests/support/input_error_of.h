#pragma once
// The message test code fails with as bad input (core/input_error.h), or "" when it
// succeeds: what the reader and builder tests check refusals by.
#include <string>

#include "core/input_error.h"

namespace landsim::testing {

template <class F>
std::string input_error_of(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace landsim::testing
