#include "io/image/view_transform.h"

#include <algorithm>
#include <filesystem>

#include "io/base/input_file.h"
#include "io/base/loadable_module.h"
#include "io/image/ocio_module.h"

namespace rt {

const char* const kBlenderConfigs[] = {"/usr/share/blender/datafiles/colormanagement/config.ocio",
                                       "/usr/share/blender/4.2/datafiles/colormanagement/config.ocio",
                                       "/usr/share/blender/3.4/datafiles/colormanagement/config.ocio", nullptr};

// OpenColorIO lives in librtcli-ocio.so (io/image/ocio_module.h), loaded by the first view asked for.
struct ViewTransform::Processor {
  std::shared_ptr<const LoadableModule> module;  // declared first: outlives the processor it made
  std::unique_ptr<OcioProcessor> ocio;
};

ViewTransform::ViewTransform() : processor_(std::make_unique<Processor>()) {}
ViewTransform::~ViewTransform() = default;

namespace {

constexpr uint64_t kMaxConfigBytes = uint64_t{4} << 20;  // Blender's is 10 KB

}  // namespace

std::string ViewTransform::blender_config() {
  for (const char* const* p = kBlenderConfigs; *p; ++p) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(*p, ec)) return *p;
  }
  return "";
}

std::shared_ptr<const ViewTransform> ViewTransform::open(const std::string& config_path, const std::string& view,
                                                         const std::string& looks, std::string& error) {
  // Read as any input (a regular file, bounded), so that a FIFO or a device is refused, not waited on.
  const auto text = read_input_text(config_path, kMaxConfigBytes, error);
  if (!text) return nullptr;
  std::string module_error;
  std::shared_ptr<const LoadableModule> module = LoadableModule::open("rtcli-ocio", module_error);
  OpenOcioView* open_view = module ? module->function<OpenOcioView>(kOpenOcioViewSymbol, module_error) : nullptr;
  if (!open_view) {
    error = "OpenColorIO is not available: " + module_error;
    return nullptr;
  }
  OcioViewRequest request;
  request.config_text = *text;
  std::error_code ec;
  request.working_dir = std::filesystem::absolute(config_path, ec).parent_path().string();
  request.view = view;
  request.looks = looks;
  OcioView made;
  open_view(request, made);
  if (!made.processor) {
    error = made.error;
    return nullptr;
  }
  std::shared_ptr<ViewTransform> out(new ViewTransform());
  out->processor_->module = std::move(module);
  out->processor_->ocio = std::move(made.processor);
  out->description_ = made.view + " (" + made.display + " display" +
                      (made.looks.empty() ? "" : ", look " + made.looks) + ") from " + config_path;
  return out;
}

void ViewTransform::apply(std::vector<Vec3>& pixels) const {
  if (pixels.empty()) return;
  static_assert(sizeof(Vec3) == 3 * sizeof(float));
  processor_->ocio->apply(reinterpret_cast<float*>(pixels.data()), static_cast<long>(pixels.size()));
  for (Vec3& p : pixels)
    for (int c = 0; c < 3; ++c) p[c] = p[c] > 0.0f ? std::min(p[c], 1.0f) : 0.0f;  // NaN too
}

}  // namespace rt
