#include "io/base/loadable_module.h"

#include <dlfcn.h>

#include <cstring>
#include <filesystem>

namespace rt {

std::vector<std::string> LoadableModule::search_folders() {
  std::error_code ec;
  const std::filesystem::path exe = std::filesystem::read_symlink("/proc/self/exe", ec);
  if (ec || exe.empty()) return {};
  const std::filesystem::path folder = exe.parent_path();
  return {folder.string(), (folder.parent_path() / "lib" / "rtcli").string()};
}

std::shared_ptr<const LoadableModule> LoadableModule::open(const std::string& name, std::string& error) {
  const std::string file = "lib" + name + ".so";
  const std::vector<std::string> folders = search_folders();
  for (const std::string& folder : folders) {
    const std::string path = folder + "/" + file;
    std::error_code ec;
    if (!std::filesystem::is_regular_file(path, ec)) continue;
    // Loaded once per process however often it is opened (the loader counts), and kept loaded:
    // the libraries it pulls in are not written to be unloaded.
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL | RTLD_NODELETE);
    if (!handle) {
      const char* why = dlerror();
      error = "could not load " + path + ": " + (why ? why : "unknown reason");
      return nullptr;
    }
    std::shared_ptr<const LoadableModule> module(new LoadableModule(handle, path));
    const auto abi = module->function<const char*()>(kModuleAbiSymbol, error);
    if (!abi) return nullptr;
    if (std::strcmp(abi(), kModuleAbi) != 0) {
      error = path + " was built for another rtcli (" + abi() + ", this one is " + kModuleAbi +
              "): build both again, or install them together (cmake --install)";
      return nullptr;
    }
    return module;
  }
  std::string where;
  for (const std::string& folder : folders) where += (where.empty() ? "" : " or ") + folder;
  error = file + " not found in " + (where.empty() ? "the executable's folder (unknown)" : where) +
          ": build it with rtcli (cmake --build) and keep it beside rtcli, or install both (cmake --install)";
  return nullptr;
}

void* LoadableModule::address(const char* symbol, std::string& error) const {
  void* p = dlsym(handle_, symbol);
  if (!p) error = path_ + " has no function " + symbol + ": not an rtcli module, or a damaged one";
  return p;
}

LoadableModule::~LoadableModule() { dlclose(handle_); }

}  // namespace rt
