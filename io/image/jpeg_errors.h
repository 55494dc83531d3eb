// libjpeg reports a fatal error by calling error_exit, which must not return: the JPEG decoder and
// writer both install this one, which keeps libjpeg's message and jumps back to their setjmp.
// Between that setjmp and the last libjpeg call they make no object with a destructor.
#pragma once

#include <csetjmp>
#include <cstdio>

#include <jpeglib.h>

namespace rt {

struct JpegErrorManager {
  jpeg_error_mgr base;  // first: libjpeg sees a jpeg_error_mgr*
  std::jmp_buf jump;
  char message[JMSG_LENGTH_MAX];
};

// error_exit for a JpegErrorManager: formats the message into it and longjmps to its `jump`.
extern "C" void rt_jpeg_jump_out(j_common_ptr cinfo);

}  // namespace rt
