#include "io/image/view_transform.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <sstream>

#include <OpenColorIO/OpenColorIO.h>

#include "io/base/input_file.h"

namespace OCIO = OCIO_NAMESPACE;

namespace rt {

const char* const kBlenderConfigs[] = {"/usr/share/blender/datafiles/colormanagement/config.ocio",
                                       "/usr/share/blender/4.2/datafiles/colormanagement/config.ocio",
                                       "/usr/share/blender/3.4/datafiles/colormanagement/config.ocio", nullptr};

struct ViewTransform::Processor {
  OCIO::ConstCPUProcessorRcPtr cpu;
};

ViewTransform::ViewTransform() : processor_(std::make_unique<Processor>()) {}
ViewTransform::~ViewTransform() = default;

namespace {

constexpr uint64_t kMaxConfigBytes = uint64_t{4} << 20;  // Blender's is 10 KB

bool same_name(std::string a, std::string b) {
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
  try {
    std::istringstream in(*text);
    OCIO::ConstConfigRcPtr read = OCIO::Config::CreateFromStream(in);
    // Its LUTs are found beside it, as when OpenColorIO opens the file itself.
    OCIO::ConfigRcPtr config = read->createEditableCopy();
    config->setWorkingDir(std::filesystem::absolute(config_path).parent_path().string().c_str());
    const char* display = config->getDefaultDisplay();
    std::vector<std::string> views;
    std::string chosen;
    for (int i = 0; i < config->getNumViews(display); ++i) {
      views.emplace_back(config->getView(display, i));
      if (same_name(views.back(), view)) chosen = views.back();
    }
    if (chosen.empty()) {
      error = "expected a view of the config's display \"" + std::string(display) + "\" (" + quoted_list(views) +
              "), found \"" + view + "\"";
      return nullptr;
    }
    std::string look_names;
    if (!looks.empty()) {
      std::vector<std::string> known;
      std::string matched;
      for (int i = 0; i < config->getNumLooks(); ++i) {
        known.emplace_back(config->getLookNameByIndex(i));
        if (same_name(known.back(), looks)) matched = known.back();
      }
      if (matched.empty()) {
        error = "expected one of the config's looks (" + quoted_list(known) + "), found \"" + looks + "\"";
        return nullptr;
      }
      look_names = matched;
    }
    auto transform = OCIO::DisplayViewTransform::Create();
    transform->setSrc(OCIO::ROLE_SCENE_LINEAR);
    transform->setDisplay(display);
    transform->setView(chosen.c_str());
    auto pipeline = OCIO::LegacyViewingPipeline::Create();
    pipeline->setDisplayViewTransform(transform);
    if (!look_names.empty()) {
      pipeline->setLooksOverrideEnabled(true);
      pipeline->setLooksOverride(look_names.c_str());
    }
    std::shared_ptr<ViewTransform> out(new ViewTransform());
    out->processor_->cpu = pipeline->getProcessor(config, config->getCurrentContext())->getDefaultCPUProcessor();
    out->description_ = chosen + " (" + display + " display" + (look_names.empty() ? "" : ", look " + look_names) +
                        ") from " + config_path;
    return out;
  } catch (const OCIO::Exception& e) {
    error = "not a usable OpenColorIO config: " + std::string(e.what());
    return nullptr;
  }
}

void ViewTransform::apply(std::vector<Vec3>& pixels) const {
  if (pixels.empty()) return;
  static_assert(sizeof(Vec3) == 3 * sizeof(float));
  OCIO::PackedImageDesc image(reinterpret_cast<float*>(pixels.data()), static_cast<long>(pixels.size()), 1, 3);
  processor_->cpu->apply(image);
  for (Vec3& p : pixels)
    for (int c = 0; c < 3; ++c) p[c] = p[c] > 0.0f ? std::min(p[c], 1.0f) : 0.0f;  // NaN too
}

}  // namespace rt
