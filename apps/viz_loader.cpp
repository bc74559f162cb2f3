#include "viz_loader.h"

#include <dlfcn.h>
#include <unistd.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace metricmap::cli {
namespace {

std::string executableDir() {
  std::vector<char> buf(4096);
  const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return ".";
  const std::string exe(buf.data(), static_cast<std::size_t>(n));
  const auto slash = exe.find_last_of('/');
  return slash == std::string::npos ? "." : exe.substr(0, slash);
}

const viz::Module* load() {
  const std::string dir = executableDir();
  const std::string candidates[] = {dir + "/libmetricmap_viz.so",
                                    dir + "/" METRICMAP_VIZ_RELDIR "/libmetricmap_viz.so"};
  std::string errors;
  for (const std::string& path : candidates) {
    void* handle = ::dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
      const char* e = ::dlerror();
      errors += std::string(errors.empty() ? "" : "; ") + (e != nullptr ? e : path);
      continue;
    }
    using Entry = const viz::Module* (*)();
    auto entry = reinterpret_cast<Entry>(::dlsym(handle, "metricmap_viz_module"));
    const viz::Module* m = entry != nullptr ? entry() : nullptr;
    if (m == nullptr || m->abi != viz::kModuleAbi)
      throw std::runtime_error(path + ": not a drawing module of this metricmap version");
    return m;
  }
  throw std::runtime_error("the drawing module libmetricmap_viz.so cannot be loaded: " + errors);
}

}  // namespace

const viz::Module& drawingModule() {
  static const viz::Module* module = load();
  return *module;
}

}  // namespace metricmap::cli
