#pragma once
// What a library under OpenImageIO prints on the process's standard error by itself: libpng's
// default handlers write "libpng error: ..." before OpenImageIO reports the same error (and
// "libpng warning: ..." about a file's metadata), so a truncated PNG reached the user as a
// stray line before landsim's own message. While an image is read, standard error (the file
// descriptor) goes to a temporary file; afterwards every line is written back except
// libpng's own, whose errors OpenImageIO's message carries. Reads that hold it are
// serialised; another thread's output in the meantime is delayed, never lost.
#include <functional>

namespace landsim::images {

// Runs `read` with libpng's own lines held back from standard error.
bool without_library_noise(const std::function<bool()>& read);

}  // namespace landsim::images
