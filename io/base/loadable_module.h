// A part of rtcli built as a shared object of its own and loaded when first asked for: the
// OpenColorIO view transforms (librtcli-ocio.so) and the watch page's HTTP server
// (librtcli-http.so). Linking their libraries into the executable made every run of rtcli load
// them (OpenColorIO; cpp-httplib with OpenSSL and Brotli, whose start-up reads openssl.cnf):
// about 10 ms of each start, 40% of `rtcli validate` on a small scene, for options few runs use.
//
// A module is looked for only beside the running executable (its build folder) and in
// ../lib/rtcli from it (`cmake --install`), by absolute path: never through the library search
// path, the working folder or the environment, so no input file or variable can choose the code
// loaded. A module built by another version or compiler is refused (its kModuleAbi differs).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace rt {

// What a module and the executable loading it must agree on: the project's version and the
// compiler (both sides pass C++ objects: std::string, std::function, virtual classes).
inline constexpr char kModuleAbi[] = RTCLI_MODULE_ABI;
// Each module defines this function, extern "C", returning its kModuleAbi.
inline constexpr char kModuleAbiSymbol[] = "rtcli_module_abi";

class LoadableModule {
 public:
  // The module `name` ("rtcli-ocio": the file librtcli-ocio.so), loaded or already loaded.
  // Null, with `error` saying where it was looked for and why it could not be used.
  static std::shared_ptr<const LoadableModule> open(const std::string& name, std::string& error);
  // The folders searched, in order.
  static std::vector<std::string> search_folders();

  // The module's extern "C" function `symbol`, of type F; null, with `error`, if it has none.
  template <class F>
  F* function(const char* symbol, std::string& error) const {
    return reinterpret_cast<F*>(address(symbol, error));
  }
  const std::string& path() const { return path_; }

  ~LoadableModule();
  LoadableModule(const LoadableModule&) = delete;
  LoadableModule& operator=(const LoadableModule&) = delete;

 private:
  LoadableModule(void* handle, std::string path) : handle_(handle), path_(std::move(path)) {}
  void* address(const char* symbol, std::string& error) const;

  void* handle_;
  std::string path_;
};

}  // namespace rt
