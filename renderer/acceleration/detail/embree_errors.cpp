#include "renderer/acceleration/detail/embree_errors.h"

#include <spdlog/spdlog.h>

#include <stdexcept>

namespace landsim::renderer::detail {

std::string embree_error_name(RTCError code) {
  switch (code) {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_UNKNOWN:
      return "unknown error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
  }
  return "error " + std::to_string(static_cast<int>(code));
}

void EmbreeErrors::watch(RTCDevice device) { rtcSetDeviceErrorFunction(device, record, this); }

void EmbreeErrors::record(void* self, RTCError code, const char* message) {
  auto* errors = static_cast<EmbreeErrors*>(self);
  const std::string text =
      embree_error_name(code) + (message && *message ? std::string(" (") + message + ")" : "");
  spdlog::debug("Embree: {}", text);
  const std::lock_guard lock(errors->mutex_);
  if (errors->first_.empty()) errors->first_ = text;  // later errors follow from the first
}

void EmbreeErrors::check(const std::string& phase) const {
  const std::lock_guard lock(mutex_);
  if (!first_.empty()) throw std::runtime_error("Embree failed while " + phase + ": " + first_);
}

}  // namespace landsim::renderer::detail
