#pragma once
// What every fuzz target shares: bad input must end in InputError (a located message, exit
// code 2 in the program); anything else that escapes (another exception, a crash, a leak,
// undefined behaviour, a hang, too much memory) is a finding.
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "core/input_error.h"

namespace landsim::fuzz {

inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// Runs `parse`; a refusal (InputError) is the expected answer to bad input.
template <typename Parse>
int refused_or_read(Parse&& parse) {
  try {
    parse();
  } catch (const InputError&) {
  }
  return 0;
}

}  // namespace landsim::fuzz
