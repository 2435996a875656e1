#include "modules/images/library_noise.h"

#include <unistd.h>

#include <cstdio>
#include <mutex>
#include <string>

namespace landsim::images {
namespace {

bool libpng_own(const std::string& line) {
  return line.rfind("libpng error: ", 0) == 0 || line.rfind("libpng warning: ", 0) == 0;
}

// Standard error redirected to a temporary file for this object's life.
class HeldStderr {
 public:
  HeldStderr() {
    std::fflush(stderr);
    file_ = std::tmpfile();
    saved_ = file_ != nullptr ? ::dup(STDERR_FILENO) : -1;
    if (saved_ < 0 || ::dup2(::fileno(file_), STDERR_FILENO) < 0) release();
  }
  ~HeldStderr() { write_back(); }
  HeldStderr(const HeldStderr&) = delete;
  HeldStderr& operator=(const HeldStderr&) = delete;

 private:
  void write_back() {
    if (file_ == nullptr || saved_ < 0) return release();
    std::fflush(stderr);
    ::dup2(saved_, STDERR_FILENO);
    std::rewind(file_);
    std::string line;
    for (int c = std::fgetc(file_); c != EOF; c = std::fgetc(file_)) {
      line += static_cast<char>(c);
      if (c == '\n') flush_line(line);
    }
    flush_line(line);
    std::fflush(stderr);
    release();
  }

  static void flush_line(std::string& line) {
    if (!line.empty() && !libpng_own(line)) std::fwrite(line.data(), 1, line.size(), stderr);
    line.clear();
  }

  void release() {
    if (saved_ >= 0) ::close(saved_);
    if (file_ != nullptr) std::fclose(file_);
    saved_ = -1;
    file_ = nullptr;
  }

  std::FILE* file_ = nullptr;
  int saved_ = -1;
};

}  // namespace

bool without_library_noise(const std::function<bool()>& read) {
  static std::mutex one_at_a_time;  // standard error is the process's, not a thread's
  const std::lock_guard<std::mutex> lock(one_at_a_time);
  const HeldStderr held;
  return read();
}

}  // namespace landsim::images
