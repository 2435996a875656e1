#pragma once
// landsim's modules: the parts that need libraries with long dependency chains (GDAL for
// rasters, OpenImageIO and OpenColorIO for PNG and texture files) are shared libraries of
// their own, loaded the first time a command needs them. Linked into the program, their
// hundreds of libraries were loaded (and, being built with BIND_NOW, symbol-resolved) at
// every start, even for `landsim --version` (docs/PERFORMANCE.md "Start-up").
//
// A module exports one C function returning a table of function pointers; the table's type
// is declared in the header of the library that uses it (terrain/raster_io.h,
// renderer/output/image_io.h).
#include <dlfcn.h>

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <string>

namespace landsim {

// A module that cannot be loaded: the installation is incomplete (not a bug, not bad input).
class ModuleError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// The folder a library embedding landsim keeps the modules in (the Python package's own
// folder: the running program there is python3); empty: none.
inline std::filesystem::path& embedded_module_directory() {
  static std::filesystem::path dir;
  return dir;
}

// Where modules are looked for: $LANDSIM_MODULE_DIR when set, else the embedding library's
// folder when one is set, else the running program's own folder (the build writes programs
// and modules to one folder).
inline std::filesystem::path module_directory() {
  if (const char* dir = std::getenv("LANDSIM_MODULE_DIR"); dir != nullptr && *dir != '\0')
    return dir;
  if (!embedded_module_directory().empty()) return embedded_module_directory();
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  return ec ? std::filesystem::path(".") : exe.parent_path();
}

// The table `symbol()` of liblandsim_<module>.so, loading the module on first use. Throws
// ModuleError naming the file and the loader's reason when it cannot be loaded.
template <class Table>
const Table& module_table(const char* module, const char* symbol) {
  static const Table* table = nullptr;
  static std::once_flag once;
  std::call_once(once, [&] {
    const std::filesystem::path file =
        module_directory() / (std::string("liblandsim_") + module + ".so");
    // RTLD_LOCAL: the module's libraries stay out of the program's symbol lookup.
    void* handle = dlopen(file.c_str(), RTLD_NOW | RTLD_LOCAL);
    const char* why = handle == nullptr ? dlerror() : nullptr;
    void* entry = handle != nullptr ? dlsym(handle, symbol) : nullptr;
    if (entry == nullptr) {
      throw ModuleError("cannot load landsim's " + std::string(module) + " module " +
                        file.string() + ": " + (why != nullptr ? why : dlerror()) +
                        " (set LANDSIM_MODULE_DIR to the folder that holds it)");
    }
    using Entry = const Table* (*)();
    table = reinterpret_cast<Entry>(entry)();
  });
  return *table;
}

}  // namespace landsim
