// librtcli-ocio.so: OpenColorIO behind io/image/ocio_module.h, loaded by ViewTransform::open.
#include "io/image/ocio_module.h"

#include <cctype>
#include <sstream>
#include <vector>

#include <OpenColorIO/OpenColorIO.h>

#include "io/base/loadable_module.h"

namespace OCIO = OCIO_NAMESPACE;

namespace rt {
namespace {

bool same_name(const std::string& a, const std::string& b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i)
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  return true;
}

std::string quoted_list(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& n : names) out += (out.empty() ? "\"" : ", \"") + n + "\"";
  return out.empty() ? "none" : out;
}

class CpuProcessor final : public OcioProcessor {
 public:
  explicit CpuProcessor(OCIO::ConstCPUProcessorRcPtr cpu) : cpu_(std::move(cpu)) {}
  void apply(float* rgb, long pixels) const override {
    OCIO::PackedImageDesc image(rgb, pixels, 1, 3);
    cpu_->apply(image);
  }

 private:
  OCIO::ConstCPUProcessorRcPtr cpu_;
};

void open_view(const OcioViewRequest& request, OcioView& out) {
  std::istringstream in(request.config_text);
  OCIO::ConstConfigRcPtr read = OCIO::Config::CreateFromStream(in);
  // Its LUTs are found beside it, as when OpenColorIO opens the file itself.
  OCIO::ConfigRcPtr config = read->createEditableCopy();
  config->setWorkingDir(request.working_dir.c_str());
  const char* display = config->getDefaultDisplay();
  std::vector<std::string> views;
  for (int i = 0; i < config->getNumViews(display); ++i) {
    views.emplace_back(config->getView(display, i));
    if (same_name(views.back(), request.view)) out.view = views.back();
  }
  if (out.view.empty()) {
    out.error = "expected a view of the config's display \"" + std::string(display) + "\" (" + quoted_list(views) +
                "), found \"" + request.view + "\"";
    return;
  }
  if (!request.looks.empty()) {
    std::vector<std::string> known;
    for (int i = 0; i < config->getNumLooks(); ++i) {
      known.emplace_back(config->getLookNameByIndex(i));
      if (same_name(known.back(), request.looks)) out.looks = known.back();
    }
    if (out.looks.empty()) {
      out.error = "expected one of the config's looks (" + quoted_list(known) + "), found \"" + request.looks + "\"";
      return;
    }
  }
  auto transform = OCIO::DisplayViewTransform::Create();
  transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
  transform->setDisplay(display);
  transform->setView(out.view.c_str());
  auto pipeline = OCIO::LegacyViewingPipeline::Create();
  pipeline->setDisplayViewTransform(transform);
  if (!out.looks.empty()) {
    pipeline->setLooksOverrideEnabled(true);
    pipeline->setLooksOverride(out.looks.c_str());
  }
  out.display = display;
  out.processor = std::make_unique<CpuProcessor>(
      pipeline->getProcessor(config, config->getCurrentContext())->getDefaultCPUProcessor());
}

}  // namespace
}  // namespace rt

extern "C" __attribute__((visibility("default"))) const char* rtcli_module_abi() { return rt::kModuleAbi; }

extern "C" __attribute__((visibility("default"))) void rtcli_open_ocio_view(const rt::OcioViewRequest& request,
                                                                            rt::OcioView& out) {
  try {
    rt::open_view(request, out);
  } catch (const std::exception& e) {  // OCIO::Exception and what else it throws
    out = rt::OcioView{};
    out.error = "not a usable OpenColorIO config: " + std::string(e.what());
  }
}
