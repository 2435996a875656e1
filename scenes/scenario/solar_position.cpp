#include "scenes/scenario/solar_position.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace landsim::scenes {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

int day_of_year(int year, int month, int day) {
  static constexpr int kBefore[12] = {0, 31, 59, 90, 120, 151, 181, 212, 243, 273, 304, 334};
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  return kBefore[month - 1] + day + (leap && month > 2 ? 1 : 0);
}

}  // namespace

SolarPosition solar_position(int year, int month, int day, double hour_utc, double latitude_deg,
                             double longitude_deg) {
  const bool leap = (year % 4 == 0 && year % 100 != 0) || year % 400 == 0;
  const double g = 2.0 * std::numbers::pi / (leap ? 366.0 : 365.0) *
                   (day_of_year(year, month, day) - 1 + (hour_utc - 12.0) / 24.0);
  const double eqtime =
      229.18 * (0.000075 + 0.001868 * std::cos(g) - 0.032077 * std::sin(g) -
                0.014615 * std::cos(2 * g) - 0.040849 * std::sin(2 * g));  // minutes
  const double decl = 0.006918 - 0.399912 * std::cos(g) + 0.070257 * std::sin(g) -
                      0.006758 * std::cos(2 * g) + 0.000907 * std::sin(2 * g) -
                      0.002697 * std::cos(3 * g) + 0.00148 * std::sin(3 * g);
  const double true_solar_minutes = hour_utc * 60.0 + eqtime + 4.0 * longitude_deg;
  const double hour_angle = (true_solar_minutes / 4.0 - 180.0) * kDeg;
  const double lat = latitude_deg * kDeg;
  const double cos_zenith = std::clamp(
      std::sin(lat) * std::sin(decl) + std::cos(lat) * std::cos(decl) * std::cos(hour_angle), -1.0,
      1.0);
  SolarPosition p;
  p.elevation_deg = 90.0 - std::acos(cos_zenith) / kDeg;
  p.azimuth_deg = std::atan2(std::sin(hour_angle), std::cos(hour_angle) * std::sin(lat) -
                                                       std::tan(decl) * std::cos(lat)) /
                      kDeg +
                  180.0;
  p.azimuth_deg = std::fmod(p.azimuth_deg + 360.0, 360.0);
  p.day_of_year = day_of_year(year, month, day);
  return p;
}

}  // namespace landsim::scenes
