# Every third-party library landsim uses, found once, from Debian 12 packages
# (scripts/install-deps.sh installs them). See ../docs/ARCHITECTURE.md.
find_package(PkgConfig REQUIRED)
find_package(embree 3 REQUIRED)
find_package(OpenEXR REQUIRED)
find_package(GDAL CONFIG REQUIRED)
find_package(TBB REQUIRED)
find_package(tomlplusplus REQUIRED)
find_package(CLI11 REQUIRED)
find_package(spdlog REQUIRED)
find_package(fmt REQUIRED)
find_package(nlohmann_json REQUIRED)
find_package(assimp REQUIRED)
find_package(kissfft CONFIG REQUIRED COMPONENTS SHARED float)  # the sensor optics' FFT (BSD-3-Clause)
# OpenImageIO 2.4's CMake config requires OpenCV headers; OpenColorIO 2.1 ships pkg-config only.
pkg_check_modules(OIIO REQUIRED IMPORTED_TARGET OpenImageIO)
pkg_check_modules(OCIO REQUIRED IMPORTED_TARGET OpenColorIO)
# NetCDF-4 with CF conventions: the measures' output for xarray users.
pkg_check_modules(NETCDF REQUIRED IMPORTED_TARGET netcdf)
if(LANDSIM_BUILD_TESTS)
  find_package(GTest REQUIRED)
  # Zstandard writes the test TIFFs OpenImageIO cannot (it writes no Zstandard TIFF).
  pkg_check_modules(ZSTD REQUIRED IMPORTED_TARGET libzstd)
endif()
if(LANDSIM_BUILD_BENCH)
  find_package(benchmark REQUIRED)
endif()
