#pragma once
// What every fuzz target shares: bad input must end in InputError (a located message, exit
// code 2 in the program); anything else that escapes (another exception, a crash, a leak,
// undefined behaviour, a hang, too much memory) is a finding.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>

#include <unistd.h>

#include "core/input_error.h"

namespace landsim::fuzz {

inline std::string_view text_of(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// The input as a file (readers that take a path: meshes, images, POV-Ray scenes, image
// sets), named `name` in a folder of this process's own; rewritten for every input.
inline std::filesystem::path input_file(const std::uint8_t* data, std::size_t size,
                                        const std::string& name) {
  static const std::filesystem::path dir = [] {
    const auto d = std::filesystem::temp_directory_path() /
                   ("landsim-fuzz-" + std::to_string(static_cast<long>(::getpid())));
    std::filesystem::create_directories(d);
    return d;
  }();
  const std::filesystem::path file = dir / name;
  std::filesystem::create_directories(file.parent_path());
  std::ofstream(file, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  return file;
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
