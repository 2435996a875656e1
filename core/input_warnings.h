#pragma once
// Input that is accepted but probably not what was meant: a silent wrong scene (a feature-map
// bit with no species, a species no cell selects, a camera under the ground, an Arbaro file
// leaning on defaults). Each warning names its file (and line where there is one), is
// reported once per process, and under --strict is refused as an InputError (exit 2).
#include <functional>
#include <iostream>
#include <mutex>
#include <set>
#include <string>

#include "core/input_error.h"

namespace landsim {

struct InputWarnings {
  std::mutex mutex;
  std::set<std::string> said;
  bool strict = false;
  std::function<void(const std::string&)> sink;  // default: stderr
};

inline InputWarnings& input_warnings() {
  static InputWarnings w;
  return w;
}

inline void warn_input(const std::string& message) {
  InputWarnings& w = input_warnings();
  const std::lock_guard lock(w.mutex);
  if (w.strict) throw InputError(message + " (refused: --strict)");
  if (!w.said.insert(message).second) return;
  if (w.sink) {
    w.sink(message);
  } else {
    std::cerr << "landsim: warning: " << message << "\n";
  }
}

}  // namespace landsim
