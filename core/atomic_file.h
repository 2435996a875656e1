#pragma once
// Outputs are written under a temporary sibling name and renamed into place only when
// complete, so an interrupted or failed run never leaves a half-written file behind.
#include <unistd.h>
#include <atomic>
#include <filesystem>
#include <fstream>
#include <string>
#include <system_error>

namespace landsim {

class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path final_path)
      : final_(std::move(final_path)), temp_(make_temp_name(final_)) {}
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  ~AtomicFile() {
    if (!committed_) {
      std::error_code ignored;
      std::filesystem::remove(temp_, ignored);
    }
  }

  // Where the writer puts the bytes. It keeps the final extension, since some writers
  // choose the file format from it.
  const std::filesystem::path& temp_path() const { return temp_; }
  const std::filesystem::path& final_path() const { return final_; }

  // Renames the finished temporary file over the final name (atomic on POSIX).
  void commit() {
    std::filesystem::rename(temp_, final_);
    committed_ = true;
  }

 private:
  static std::filesystem::path make_temp_name(const std::filesystem::path& p) {
    static std::atomic<unsigned> counter{0};
    // Appended piecewise: GCC 12 warns falsely (-Wrestrict) on a chain of operator+.
    std::string name(".");
    name.append(p.stem().string()).append(".tmp-").append(std::to_string(::getpid()));
    name.append("-").append(std::to_string(counter++)).append(p.extension().string());
    return p.parent_path() / name;
  }

  std::filesystem::path final_;
  std::filesystem::path temp_;
  bool committed_ = false;
};

// `text` as the whole of `path`, written atomically (reports, manifests, tables).
inline void write_file_atomically(const std::filesystem::path& path, const std::string& text) {
  AtomicFile file(path);
  std::ofstream(file.temp_path()) << text;
  file.commit();
}

}  // namespace landsim
