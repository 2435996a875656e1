#include "renderer/acceleration/detail/embree_errors.h"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

namespace landsim::renderer::detail {
namespace {

TEST(EmbreeErrors, AReportedErrorBecomesAnExceptionNamingThePhase) {
  RTCDevice device = rtcNewDevice(nullptr);
  ASSERT_NE(device, nullptr);
  EmbreeErrors errors;
  errors.watch(device);
  EXPECT_NO_THROW(errors.check("doing nothing"));
  // A vertex buffer that is not there: Embree reports an error and would carry on.
  RTCGeometry geom = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  rtcSetGeometryBuffer(geom, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, nullptr, 0, 12, 3);
  rtcReleaseGeometry(geom);
  try {
    errors.check("building a test mesh");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("Embree failed while building a test mesh"), std::string::npos) << what;
    EXPECT_NE(what.find("invalid"), std::string::npos) << what;  // Embree's reason
  }
  rtcReleaseDevice(device);
}

TEST(EmbreeErrors, CodesHaveNames) {
  EXPECT_EQ(embree_error_name(RTC_ERROR_OUT_OF_MEMORY), "out of memory");
  EXPECT_EQ(embree_error_name(RTC_ERROR_INVALID_ARGUMENT), "invalid argument");
}

}  // namespace
}  // namespace landsim::renderer::detail
