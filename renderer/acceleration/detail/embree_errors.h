#pragma once
// Private to renderer/: Embree reports errors through a device callback and then carries on
// with an unusable scene (a render would crash inside it). This records the first error and
// turns it into an exception naming what was being built, so a failed build (out of memory,
// for one) ends the command cleanly with exit 1 instead of a crash.
#include <embree3/rtcore.h>

#include <mutex>
#include <string>

namespace landsim::renderer::detail {

class EmbreeErrors {
 public:
  // Installs the callback on `device`; this object must outlive the device's use.
  void watch(RTCDevice device);
  // Throws std::runtime_error("Embree failed while <phase>: ...") if any error was reported.
  void check(const std::string& phase) const;

 private:
  static void record(void* self, RTCError code, const char* message);
  mutable std::mutex mutex_;
  std::string first_;  // the first error's description, empty if none
};

// Embree's name for an error code ("out of memory", ...).
std::string embree_error_name(RTCError code);

}  // namespace landsim::renderer::detail
