#pragma once
// The sun's position from date, time and place (NOAA's approximation of the solar
// ephemeris: equation of time and declination as Fourier series in the day of year; about
// 0.5 degrees at most from the precise position, which is far below a pixel's worth here).
namespace landsim::scenes {

struct SolarPosition {
  double elevation_deg = 0.0;  // above the horizon
  double azimuth_deg = 0.0;    // clockwise from north
  int day_of_year = 1;         // 1 on 1 January
};

// `hour` in decimal hours of Coordinated Universal Time; latitude north and longitude east
// positive, degrees.
SolarPosition solar_position(int year, int month, int day, double hour_utc, double latitude_deg,
                             double longitude_deg);

}  // namespace landsim::scenes
