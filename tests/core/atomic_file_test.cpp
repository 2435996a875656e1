#include "core/atomic_file.h"

#include <gtest/gtest.h>

#include <fstream>

#include "tests/support/temp_dir.h"

namespace landsim {
namespace {

int file_count(const std::filesystem::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, CommitRenamesIntoPlace) {
  testing::TempDir dir;
  const auto target = dir / "image.exr";
  {
    AtomicFile f(target);
    EXPECT_EQ(f.temp_path().extension(), ".exr");  // writers pick formats by extension
    EXPECT_NE(f.temp_path(), target);
    std::ofstream(f.temp_path()) << "done";
    EXPECT_FALSE(std::filesystem::exists(target));
    f.commit();
  }
  EXPECT_EQ(testing::read_file(target), "done");
  EXPECT_EQ(file_count(dir.path()), 1);
}

TEST(AtomicFile, AbandonedWriteLeavesNothing) {
  testing::TempDir dir;
  {
    AtomicFile f(dir / "image.exr");
    std::ofstream(f.temp_path()) << "half";
  }
  EXPECT_EQ(file_count(dir.path()), 0);
}

}  // namespace
}  // namespace landsim
