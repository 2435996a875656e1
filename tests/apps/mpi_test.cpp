// The MPI path end to end: landsim under `mpirun -np 2` against landsim alone.
#include <gtest/gtest.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <set>

#include "tests/support/run_program.h"
#include "tests/support/temp_dir.h"

namespace landsim {
namespace {

using testing::TempDir;

// Two ranks on however many cores there are (and as root, as CI runs); `wrapper` (e.g.
// "timeout 300") runs mpirun under another command.
testing::ProgramResult run_mpi(const std::string& args, const TempDir& dir,
                               const std::string& wrapper = "") {
  const std::string root = ::geteuid() == 0 ? " --allow-run-as-root" : "";
  return testing::run_command(wrapper + (wrapper.empty() ? "" : " ") + LANDSIM_MPIRUN +
                                  " --oversubscribe" + root + " -np 2 " + LANDSIM_BINARY + " " +
                                  args,
                              dir);
}

// Two views, two frames, trees (so that tiles differ in cost), small images.
std::filesystem::path image_set(const TempDir& dir, const std::string& more_views = "") {
  const std::string data = testing::source_file("data").string();
  return dir.write("set.toml",
                   "[terrain]\nelevation = \"" + data +
                       "/terrain/volcano.asc\"\n"
                       "[sun]\nelevation = 30\nazimuth = 300\n"
                       "[featuremaps]\nclasses = \"" +
                       data +
                       "/featuremaps/volcano_landcover.asc\"\n"
                       "class_map = \"" +
                       testing::source_file("scenes/examples/volcano_classes.toml").string() +
                       "\"\n[[species]]\nbit = 0\nfile = \"" + data +
                       "/species/quaking_aspen.toml\"\n"
                       "variants = 2\ndensity_per_ha = 60\n"
                       "[[views]]\nname = \"a\"\nposition = [520.0, 930.0, 330.0]\ntarget = "
                       "[280.0, 280.0, 130.0]\n"
                       "width = 48\nheight = 27\n"
                       "[[views]]\nname = \"b\"\nposition = [100.0, 500.0, 250.0]\ntarget = "
                       "[300.0, 300.0, 130.0]\n"
                       "width = 40\nheight = 30\n" +
                       more_views + "[render]\nspp = 2\nframes = [0.0, 1.0]\n");
}

void expect_same_files(const std::filesystem::path& a, const std::filesystem::path& b) {
  ASSERT_EQ(testing::file_names(a), testing::file_names(b));
  for (const std::string& name : testing::file_names(a))
    EXPECT_EQ(testing::read_file(a / name), testing::read_file(b / name)) << name;
}

// Every camera model splits into the same tiles (docs/CAMERAS.md): a rolled fisheye and an
// orthographic map join the two perspective views.
const char* const kOtherCameraModels =
    "[[views]]\nname = \"fisheye\"\nposition = [100.0, 500.0, 250.0]\ntarget = [300.0, 300.0, "
    "130.0]\nprojection = \"fisheye\"\nfov = 160\nroll = 20\nwidth = 40\nheight = 30\n"
    "[[views]]\nname = \"map\"\nposition = [300.0, 400.0, 600.0]\nprojection = "
    "\"orthographic\"\npixel_size = 12.0\nwidth = 32\nheight = 24\n";

TEST(Mpi, AnImageSetSplitAcrossRanksGivesTheSameFilesBitForBit) {
  TempDir dir;
  const auto scenario = image_set(dir, kOtherCameraModels);
  const auto one =
      testing::run_landsim("render " + scenario.string() + " --out " + (dir / "one").string(), dir);
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto two =
      run_mpi("render " + scenario.string() + " --out " + (dir / "two").string() + " --json", dir);
  ASSERT_EQ(two.exit_code, 0) << two.err;
  EXPECT_NE(two.err.find("rank 0 of 2"), std::string::npos) << "logs name the rank";
  EXPECT_NE(two.out.find("\"ranks\":2"), std::string::npos) << two.out;
  EXPECT_EQ(testing::file_names(dir / "two").size(), 17u);  // 8 EXR, 8 PNG, the manifest
  expect_same_files(dir / "one", dir / "two");
}

TEST(Mpi, TaskIndexRendersExactlyOneImageAndCheckWritesTheManifest) {
  TempDir dir;
  const auto scenario = image_set(dir);
  // The count a job array is sized by (scripts/slurm/submit.sh).
  const auto info = testing::run_landsim("info " + scenario.string() + " --json", dir);
  EXPECT_NE(info.out.find("\"images\":4"), std::string::npos) << info.out;
  const auto out = dir / "tasks";
  const auto r = testing::run_landsim(
      "render " + scenario.string() + " --task-index 3 --out " + out.string(), dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Image 3 is frame 1 of view b.
  EXPECT_EQ(testing::file_names(out), (std::set<std::string>{"b_f0001.exr", "b_f0001.png"}));
  const auto incomplete =
      testing::run_landsim("render " + scenario.string() + " --check --out " + out.string(), dir);
  EXPECT_EQ(incomplete.exit_code, 1);
  EXPECT_NE(incomplete.err.find("a_f0000.exr"), std::string::npos) << incomplete.err;
  for (int k : {0, 1, 2})
    ASSERT_EQ(testing::run_landsim("render " + scenario.string() + " --task-index " +
                                       std::to_string(k) + " --out " + out.string(),
                                   dir)
                  .exit_code,
              0);
  ASSERT_EQ(
      testing::run_landsim("render " + scenario.string() + " --check --out " + out.string(), dir)
          .exit_code,
      0);
  const auto whole = testing::run_landsim(
      "render " + scenario.string() + " --out " + (dir / "whole").string(), dir);
  ASSERT_EQ(whole.exit_code, 0) << whole.err;
  expect_same_files(dir / "whole", out);  // the same images and manifest
  EXPECT_EQ(testing::run_landsim(
                "render " + scenario.string() + " --task-index 4 --out " + out.string(), dir)
                .exit_code,
            2);
}

TEST(Mpi, ARankThatFailsFailsTheJobClearly) {
  TempDir dir;
  const auto bad = dir.write("bad.toml", "[terrain]\nelevation = \"nowhere.asc\"\n");
  const auto r = run_mpi("render " + bad.string() + " --out " + (dir / "o").string(), dir);
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("rank"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("nowhere.asc"), std::string::npos) << r.err;
}

// Only rank 0 writes: when writing fails there (the second image's EXR name is taken by a
// directory) rank 1 is waiting for work, and must be aborted rather than left waiting. The
// job ends (a timeout of 5 minutes tells a hang apart), non-zero, naming rank 0 and the
// file; the first image stays, and no temporary file is left behind.
TEST(Mpi, OneFailingRankAbortsTheOthersWithoutAHang) {
  TempDir dir;
  const auto scenario = image_set(dir);
  const auto out = dir / "out";
  std::filesystem::create_directories(out / "b_f0000.exr");
  const auto r =
      run_mpi("render " + scenario.string() + " --out " + out.string(), dir, "timeout 300");
  EXPECT_NE(r.exit_code, 124) << "the job hung";
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.err.find("rank 0 of 2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("b_f0000.exr"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rank 1 of 2"), std::string::npos) << "rank 1 never started: " << r.err;
  // The first image kept with a manifest that says the set is unfinished; no temporary file.
  EXPECT_EQ(testing::file_names(out),
            (std::set<std::string>{"a_f0000.exr", "a_f0000.png", "b_f0000.exr", "manifest.json"}));
  const auto manifest = nlohmann::json::parse(std::ifstream(out / "manifest.json"));
  EXPECT_FALSE(manifest["complete"].get<bool>());
  EXPECT_EQ(manifest["images"].size(), 1u);
}

}  // namespace
}  // namespace landsim
