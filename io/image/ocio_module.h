// What the OpenColorIO module (ocio_module.cpp, built as librtcli-ocio.so; io/base/loadable_module.h)
// offers ViewTransform: a config's view and looks made into a processor. Only this header is
// shared by the module and the executable, so only the module links OpenColorIO.
#pragma once

#include <memory>
#include <string>

namespace rt {

// A display view's processor: RGB triples in place, scene-linear in, display-encoded out.
class OcioProcessor {
 public:
  virtual ~OcioProcessor() = default;
  virtual void apply(float* rgb, long pixels) const = 0;
};

struct OcioViewRequest {
  std::string config_text;  // the config file's text (read by the executable, bounded)
  std::string working_dir;  // where its LUTs are found: the config's folder
  std::string view;         // matched without regard to case
  std::string looks;        // "" for none
};

struct OcioView {
  std::unique_ptr<OcioProcessor> processor;  // null, with `error`, when there is none
  std::string view, display, looks;          // as the config names them
  std::string error;
};

// extern "C" void rtcli_open_ocio_view(const OcioViewRequest&, OcioView&)
using OpenOcioView = void(const OcioViewRequest&, OcioView&);
inline constexpr char kOpenOcioViewSymbol[] = "rtcli_open_ocio_view";

}  // namespace rt
