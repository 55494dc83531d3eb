#include "io/image/jpeg_errors.h"

namespace rt {

extern "C" void rt_jpeg_jump_out(j_common_ptr cinfo) {
  auto* manager = reinterpret_cast<JpegErrorManager*>(cinfo->err);
  (*cinfo->err->format_message)(cinfo, manager->message);
  std::longjmp(manager->jump, 1);
}

}  // namespace rt
