// SPDX-License-Identifier: LGPL-2.1-or-later
#include "output/jpeg.hpp"

#include <jpeglib.h>

#include <csetjmp>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <vector>

#include "support/error.hpp"

namespace sliceform {
namespace {

// libjpeg reports errors through a callback that must not return: it jumps back here.
struct ErrorJump {
  jpeg_error_mgr manager;
  std::jmp_buf back;
  char message[JMSG_LENGTH_MAX];
};

void jumpBack(j_common_ptr info) {
  ErrorJump* error = reinterpret_cast<ErrorJump*>(info->err);
  info->err->format_message(info, error->message);
  std::longjmp(error->back, 1);
}

}  // namespace

std::string jpegBytes(const Picture& picture, int quality) {
  if (picture.width <= 0 || picture.height <= 0 ||
      picture.pixels.size() != size_t(picture.width) * size_t(picture.height))
    throw Error(ErrorKind::Io, "cannot encode an empty picture as JPEG");
  jpeg_compress_struct info{};
  ErrorJump error{};
  info.err = jpeg_std_error(&error.manager);
  error.manager.error_exit = jumpBack;
  unsigned char* buffer = nullptr;
  unsigned long size = 0;
  // Nothing with a destructor lives between here and the jump: only plain buffers.
  std::vector<unsigned char> row(size_t(picture.width) * 3);
  if (setjmp(error.back)) {
    jpeg_destroy_compress(&info);
    std::free(buffer);
    throw Error(ErrorKind::Io, std::string("cannot encode a picture as JPEG: ") + error.message);
  }
  jpeg_create_compress(&info);
  jpeg_mem_dest(&info, &buffer, &size);
  info.image_width = static_cast<JDIMENSION>(picture.width);
  info.image_height = static_cast<JDIMENSION>(picture.height);
  info.input_components = 3;
  info.in_color_space = JCS_RGB;
  jpeg_set_defaults(&info);
  jpeg_set_quality(&info, quality, TRUE);
  for (int c = 0; c < info.num_components; ++c)
    info.comp_info[c].h_samp_factor = info.comp_info[c].v_samp_factor = 1;
  jpeg_start_compress(&info, TRUE);
  while (info.next_scanline < info.image_height) {
    const uint32_t* pixel = picture.pixels.data() + size_t(info.next_scanline) * picture.width;
    for (int x = 0; x < picture.width; ++x) {
      row[3 * x] = (pixel[x] >> 16) & 255;
      row[3 * x + 1] = (pixel[x] >> 8) & 255;
      row[3 * x + 2] = pixel[x] & 255;
    }
    JSAMPROW rows[1] = {row.data()};
    jpeg_write_scanlines(&info, rows, 1);
  }
  jpeg_finish_compress(&info);
  jpeg_destroy_compress(&info);
  std::string bytes(reinterpret_cast<const char*>(buffer), size);
  std::free(buffer);
  return bytes;
}

}  // namespace sliceform
