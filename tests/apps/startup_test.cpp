// Start-up (docs/PERFORMANCE.md "Start-up"): GDAL, OpenImageIO and OpenColorIO are modules
// loaded when first needed, not libraries of the program; commands that read no raster and
// write no image run without the modules; one that needs a missing module says which.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "tests/support/run_program.h"
#include "tests/support/temp_dir.h"

namespace landsim {
namespace {

using testing::run_command;
using testing::run_landsim;
using testing::TempDir;

const std::string kNoModules = "LANDSIM_MODULE_DIR=/nonexistent ";

TEST(Startup, ProgramDoesNotLinkTheModulesLibraries) {
  const TempDir dir;
  const auto r = run_command("ldd " + std::string(LANDSIM_BINARY), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  for (const char* lib : {"libgdal", "libOpenImageIO", "libOpenColorIO"})
    EXPECT_EQ(r.out.find(lib), std::string::npos) << lib << " is linked:\n" << r.out;
  EXPECT_NE(r.out.find("libembree3"), std::string::npos);  // the check itself works
}

TEST(Startup, CommandsThatReadNoRasterRunWithoutTheModules) {
  const TempDir dir;
  const std::string species = std::string(LANDSIM_SOURCE_DIR) + "/data/species/quaking_aspen.toml";
  EXPECT_EQ(run_command(kNoModules + LANDSIM_BINARY " --version", dir).exit_code, 0);
  const auto tree = run_command(kNoModules + LANDSIM_BINARY " tree " + species +
                                    " --seed 13 --obj " + (dir / "aspen.obj").string(),
                                dir);
  EXPECT_EQ(tree.exit_code, 0) << tree.err;
  const auto degrade = run_command(kNoModules + LANDSIM_BINARY " degrade " + species, dir);
  EXPECT_EQ(degrade.exit_code, 0) << degrade.err;
}

TEST(Startup, AMissingModuleIsNamed) {
  const TempDir dir;
  // export-obj reads the default scene's rasters (GDAL) and writes no image.
  const auto gdal =
      run_command(kNoModules + LANDSIM_BINARY " export-obj --out " + (dir / "s.obj").string(), dir);
  EXPECT_EQ(gdal.exit_code, 1);
  EXPECT_NE(gdal.err.find("landsim: error: cannot load"), std::string::npos) << gdal.err;
  EXPECT_NE(gdal.err.find("liblandsim_gdal.so"), std::string::npos) << gdal.err;
  EXPECT_NE(gdal.err.find("LANDSIM_MODULE_DIR"), std::string::npos) << gdal.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "s.obj"));
  // render loads the image module before anything else, and writes nothing without it.
  const auto images =
      run_command(kNoModules + LANDSIM_BINARY " render --spp 1 --out " + (dir / "r").string(), dir);
  EXPECT_EQ(images.exit_code, 1);
  EXPECT_NE(images.err.find("liblandsim_images.so"), std::string::npos) << images.err;
  EXPECT_FALSE(std::filesystem::exists(dir / "r"));
}

}  // namespace
}  // namespace landsim
